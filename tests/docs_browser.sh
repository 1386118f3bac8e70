#!/usr/bin/env bash
# The rendered docs checked in a real browser (ctest: docs_browser).
#   bash tests/docs_browser.sh BUILD_DIR
# Builds the docs (paper/make_docs.sh: fails on any Doxygen warning), then opens the main page, the
# paper/ pages, the page of tests by equation and every page a paper page links to (the kernels) in
# headless Chromium, lets MathJax run, and fails on
#   - a MathJax error: an element of class merror, "Undefined control sequence", "Math Processing Error";
#   - a page with formulas on which MathJax did not run;
#   - a broken link: a local href whose file or #anchor does not exist in the generated HTML.
# Exits 77 (ctest: skipped) with a clear message when Chromium is not installed (`make deps` installs it).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$root/$build
browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z $browser ]]; then
  echo "docs_browser: SKIPPED: Chromium is not installed (make deps installs Debian's chromium)."
  exit 77
fi

start=$(date +%s)
bash "$root/paper/make_docs.sh" "$build" || { echo "docs_browser: make docs failed"; exit 1; }
docs_seconds=$(( $(date +%s) - start ))
html=$build/docs/html
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The pages to open: the main page, the paper pages (page ids paper_*), the tests by equation, and
# every local page a paper page links to (the kernels, their files, the tests of each equation).
pages=(index.html tests_by_equation.html)
for file in "$html"/paper_*.html; do pages+=("$(basename "$file")"); done
linked=$(for page in "${pages[@]}"; do
  grep -o 'href="[^"#:]*\.html' "$html/$page" | sed 's/^href="//'
done | sort -u)
for page in $linked; do
  case " ${pages[*]} " in *" $page "*) ;; *) pages+=("$page") ;; esac
done

failures=0
fail() { echo "docs_browser: FAIL: $*"; failures=$((failures + 1)); }

# One Chromium run opens every page in turn in an iframe of a check page, waits for MathJax to finish
# typesetting it (MathJax.Hub.Queue), and writes what it found into the check page, which Chromium dumps.
{
  echo '<html><body><pre id="out"></pre><script>'
  printf 'var base = "file://%s/";\nvar pages = [' "$html"
  printf '"%s",' "${pages[@]}"
  echo '];'
  cat <<'JS'
var i = 0, out = document.getElementById('out');
function line(s) { out.appendChild(document.createTextNode(s + "\n")); }
function next() {
  if (i >= pages.length) { line("DONE"); return; }
  var page = pages[i++], frame = document.createElement('iframe'), reported = false;
  frame.onload = function () {
    var w = frame.contentWindow;
    var finish = function () {
      if (reported) return;
      reported = true;
      var d = w.document, text = d.body ? d.body.textContent : "";
      line(page + "\tloaded\t" + (d.body ? 1 : 0));
      line(page + "\tmathjax\t" + (w.MathJax && w.MathJax.Hub ? 1 : 0));
      line(page + "\trendered\t" + d.querySelectorAll('.MathJax, .MathJax_Display').length);
      line(page + "\tmerror\t" + d.querySelectorAll('.merror').length);
      line(page + "\tundefined\t" + (text.indexOf("Undefined control sequence") >= 0 ? 1 : 0));
      line(page + "\tprocessing\t" + (text.indexOf("Math Processing Error") >= 0 ? 1 : 0));
      var links = d.querySelectorAll('a[href]');
      for (var k = 0; k < links.length; ++k) line(page + "\thref\t" + links[k].getAttribute('href'));
      frame.remove();
      next();
    };
    if (w.MathJax && w.MathJax.Hub && w.MathJax.Hub.Queue) w.MathJax.Hub.Queue(finish); else finish();
  };
  frame.src = base + page;
  document.body.appendChild(frame);
}
next();
</script></body></html>
JS
} > "$work/check.html"
profile=$(mktemp -d "$work/profile.XXXX")
timeout 600 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync --disable-extensions \
  --allow-file-access-from-files --user-data-dir="$profile" --virtual-time-budget=600000 \
  --dump-dom "file://$work/check.html" > "$work/check.dom" 2> "$work/chromium.err"
sed -n '/<pre id="out">/,/<\/pre>/p' "$work/check.dom" | sed 's/^<html><head><\/head><body><pre id="out">//; s/<\/pre>.*//' \
  | sed 's/&amp;/\&/g' > "$work/report.tsv"
grep -qx 'DONE' "$work/report.tsv" || fail "Chromium did not get through every page (see below); its stderr: $(tail -c 500 "$work/chromium.err")"

value() { awk -F'\t' -v p="$1" -v k="$2" '$1 == p && $2 == k { print $3 }' "$work/report.tsv"; }
for page in "${pages[@]}"; do
  [[ $(value "$page" loaded) == 1 ]] || { fail "$page: not opened"; continue; }
  [[ $(value "$page" merror) == 0 ]] || fail "$page: $(value "$page" merror) MathJax errors (class merror)"
  [[ $(value "$page" undefined) == 0 ]] || fail "$page: MathJax: Undefined control sequence"
  [[ $(value "$page" processing) == 0 ]] || fail "$page: MathJax: Math Processing Error"
  # Formulas left as TeX: MathJax did not run on this page.
  if grep -q '\\(\|\\\[' "$html/$page" && [[ $(value "$page" rendered) == 0 ]]; then
    fail "$page: has formulas, but MathJax did not render them (mathjax loaded: $(value "$page" mathjax))"
  fi
  # Every local link: its file exists, and its #anchor is an id or a name in that file.
  while IFS= read -r href; do
    target=${href%%#*}
    anchor=
    [[ $href == *"#"* ]] && anchor=${href#*#}
    [[ -z $target ]] && target=$page
    [[ -f $html/$target ]] || { fail "$page: broken link to $href (no file $target)"; continue; }
    if [[ -n $anchor ]] && ! grep -q "id=\"$anchor\"\|name=\"$anchor\"" "$html/$target"; then
      fail "$page: broken link to $href (no anchor $anchor in $target)"
    fi
  done < <(value "$page" href | grep -v '^[a-z]*:' | sort -u)
done

total=$(( $(date +%s) - start ))
echo "docs_browser: ${#pages[@]} pages opened in Chromium; make docs took ${docs_seconds} s, the whole check ${total} s"
if (( failures > 0 )); then
  echo "docs_browser: $failures problems"
  exit 1
fi
echo "docs_browser: every formula rendered, every link resolves"
