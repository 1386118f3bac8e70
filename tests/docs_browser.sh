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

# Open every page after MathJax ran (virtual time lets its timers and loads finish), two at a time.
dump() {
  local page=$1 profile
  profile=$(mktemp -d "$work/profile.XXXX")
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync --disable-extensions \
    --user-data-dir="$profile" --virtual-time-budget=10000 --dump-dom "file://$html/$page" \
    > "$work/${page//\//_}.dom" 2> "$work/${page//\//_}.err"
  rm -rf "$profile"
}
export -f dump
export browser html work
printf '%s\n' "${pages[@]}" | xargs -P 2 -I{} bash -c 'dump "$@"' _ {}

for page in "${pages[@]}"; do
  dom=$work/${page//\//_}.dom
  [[ -s $dom ]] || { fail "$page: Chromium produced no DOM ($(head -c 300 "$work/${page//\//_}.err"))"; continue; }
  grep -q 'class="merror"\|class="MathJax_merror"\|merror' "$dom" && fail "$page: a MathJax error (merror): $(grep -o 'merror[^<]*<[^<]*' "$dom" | head -3 | tr '\n' ' ')"
  grep -q 'Undefined control sequence' "$dom" && fail "$page: MathJax: $(grep -o 'Undefined control sequence[^<"]*' "$dom" | sort -u | head -5 | tr '\n' ' ')"
  grep -q 'Math Processing Error' "$dom" && fail "$page: MathJax: Math Processing Error"
  # Formulas left as TeX: MathJax did not run (or did not finish) on this page.
  if grep -q 'class="formulaDsp"\|\\(\|\\\[' "$html/$page" && ! grep -q 'class="MathJax' "$dom"; then
    fail "$page: has formulas, but MathJax did not render them"
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
  done < <(grep -o 'href="[^"]*"' "$dom" | sed 's/^href="//; s/"$//' | grep -v '^[a-z]*:' | grep -v '^javascript' | sort -u)
done

total=$(( $(date +%s) - start ))
echo "docs_browser: ${#pages[@]} pages opened in Chromium; make docs took ${docs_seconds} s, the whole check ${total} s"
if (( failures > 0 )); then
  echo "docs_browser: $failures problems"
  exit 1
fi
echo "docs_browser: every formula rendered, every link resolves"
