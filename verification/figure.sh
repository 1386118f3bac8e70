# Sourced by the figure scripts of make figures and make studies: draws one figure and fails it when gnuplot
# warns (an empty data file, a missing column, an undefined value: anything on its standard error), when it exits
# non-zero, or when a legend entry has no data (a titled curve whose points are all undefined or filtered out;
# keyentry lines, which only explain a style, carry no points and pass). Needs $plots (verification/plots) and $data.
#
#   draw_figure SCRIPT.gp "GNUPLOT SETTINGS"   (the settings set at least out='...'; returns 1 on failure)
draw_figure() {
  local script=$1 settings=$2 log table rc=0
  log=$(mktemp) table=$(mktemp)
  gnuplot -e "dir='$plots'; data='$data'; table='$table'; $settings" "$plots/$script" 2>"$log" || rc=1
  if [[ -s $log ]]; then
    echo "figure $script: gnuplot said:" >&2
    sed 's/^/  /' "$log" >&2
    rc=1
  fi
  # gnuplot's table: "# Curve N of M, K points", "# Curve title: ...", then rows whose last field is i, o or u.
  local empty
  empty=$(awk '/^# Curve [0-9]+ of/ { if (title != "" && points > 0 && defined == 0) print title; title = ""; points = $(NF - 1); defined = 0; next }
    /^# Curve title:/ { sub(/^# Curve title: /, ""); title = $0; next }
    /^ *[^#]/ && ($NF == "i" || $NF == "o") { defined++ }
    END { if (title != "" && points > 0 && defined == 0) print title }' "$table")
  if [[ -n $empty ]]; then
    echo "figure $script: legend entries with no data: $(echo "$empty" | paste -sd ';' -)" >&2
    rc=1
  fi
  rm -f "$log" "$table"
  return $rc
}
