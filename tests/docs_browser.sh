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
browser=${CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}
if [[ -z $browser || ! -x $browser ]]; then
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
  [[ -f $html/$page ]] || continue  # reported below as a broken link of the page that names it
  case " ${pages[*]} " in *" $page "*) ;; *) pages+=("$page") ;; esac
done

failures=0
fail() { echo "docs_browser: FAIL: $*"; failures=$((failures + 1)); }

# One Chromium run opens the pages in iframes of a check page, four at a time (one at a time the check
# took 30 s of wall time for 8 s of CPU, four at a time 24 s; sixteen gained nothing more), waits for
# MathJax to finish typesetting each (MathJax.Hub.Queue), and writes what it found into the check page,
# which Chromium dumps.
{
  echo '<html><body><pre id="out"></pre><script>'
  printf 'var base = "file://%s/";\nvar pages = [' "$html"
  printf '"%s",' "${pages[@]}"
  echo '];'
  cat <<'JS'
var i = 0, open = 0, at_once = 4, out = document.getElementById('out');
function line(s) { out.appendChild(document.createTextNode(s + "\n")); }
function next() {
  while (open < at_once && i < pages.length) check(pages[i++]);
  if (open == 0 && i >= pages.length) line("DONE");
}
function check(page) {
  var frame = document.createElement('iframe'), reported = false;
  ++open;
  frame.onload = function () {
    var w = frame.contentWindow;
    var finish = function () {
      if (reported) return;
      reported = true;
      try { report(w); } catch (e) { line(page + "\terror\t" + e); }
      frame.remove();
      --open;
      next();
    };
    var report = function (w) {
      var d = w.document, text = d.body ? d.body.textContent : "";
      line(page + "\tloaded\t" + (d.body ? 1 : 0));
      line(page + "\tmathjax\t" + (w.MathJax && w.MathJax.Hub ? 1 : 0));
      line(page + "\trendered\t" + d.querySelectorAll('.MathJax, .MathJax_Display').length);
      line(page + "\tmerror\t" + d.querySelectorAll('.merror').length);
      line(page + "\tundefined\t" + (text.indexOf("Undefined control sequence") >= 0 ? 1 : 0));
      line(page + "\tprocessing\t" + (text.indexOf("Math Processing Error") >= 0 ? 1 : 0));
      var links = d.querySelectorAll('a[href]');
      for (var k = 0; k < links.length; ++k) line(page + "\thref\t" + links[k].getAttribute('href'));
    };
    setTimeout(finish, 30000);  // a page whose MathJax never finishes is reported, not waited for
    try {
      if (w.MathJax && w.MathJax.Hub && w.MathJax.Hub.Queue) w.MathJax.Hub.Queue(finish); else finish();
    } catch (e) { finish(); }
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
browser_seconds=$(( $(date +%s) - start - docs_seconds ))
sed -n '/<pre id="out">/,/<\/pre>/p' "$work/check.dom" | sed 's/^<html><head><\/head><body><pre id="out">//; s/<\/pre>.*//' \
  | sed 's/&amp;/\&/g' > "$work/report.tsv"
grep -qx 'DONE' "$work/report.tsv" || fail "Chromium did not get through every page (see below); its stderr: $(tail -c 500 "$work/chromium.err")"

# The findings, checked in one pass: MathJax errors, formulas left as TeX, and every local link (its
# file exists, and its #anchor is an id or a name in that file).
(cd "$html" && find . \( -type f -o -type l \) -printf '%P\n') > "$work/files.txt"
(cd "$html" && grep -o -H 'id="[^"]*"\|name="[^"]*"' -- *.html) | sed 's/:id="/#/; s/:name="/#/; s/"$//' > "$work/anchors.txt"
(cd "$html" && grep -l '\\(\|\\\[' -- "${pages[@]}") > "$work/with_formulas.txt" || true
printf '%s\n' "${pages[@]}" > "$work/pages.txt"
awk -F'\t' '
  FILENAME == ARGV[1] { files[$0] = 1; next }
  FILENAME == ARGV[2] { anchors[$0] = 1; next }
  FILENAME == ARGV[3] { formulas[$0] = 1; next }
  FILENAME == ARGV[4] { wanted[$0] = 1; order[++count] = $0; next }
  $2 == "loaded" { loaded[$1] = $3 }
  $2 == "error" { error[$1] = $3 }
  $2 == "mathjax" { mathjax[$1] = $3 }
  $2 == "rendered" { rendered[$1] = $3 }
  $2 == "merror" && $3 != 0 { print "docs_browser: FAIL: " $1 ": " $3 " MathJax errors (class merror)" }
  $2 == "undefined" && $3 != 0 { print "docs_browser: FAIL: " $1 ": MathJax: Undefined control sequence" }
  $2 == "processing" && $3 != 0 { print "docs_browser: FAIL: " $1 ": MathJax: Math Processing Error" }
  $2 == "href" && $3 !~ /^[a-z]+:/ {
    href = $3; target = href; anchor = ""
    at = index(href, "#")
    if (at > 0) { target = substr(href, 1, at - 1); anchor = substr(href, at + 1) }
    if (target == "") target = $1
    if (!(target in files)) print "docs_browser: FAIL: " $1 ": broken link to " href " (no file " target ")"
    else if (anchor != "" && target ~ /\.html$/ && !((target "#" anchor) in anchors))
      print "docs_browser: FAIL: " $1 ": broken link to " href " (no anchor " anchor " in " target ")"
  }
  END {
    for (k = 1; k <= count; ++k) {
      page = order[k]
      if (loaded[page] != 1) { print "docs_browser: FAIL: " page ": not opened " error[page]; continue }
      if ((page in formulas) && rendered[page] == 0)
        print "docs_browser: FAIL: " page ": has formulas, but MathJax did not render them (MathJax loaded: " mathjax[page] ")"
    }
  }' "$work/files.txt" "$work/anchors.txt" "$work/with_formulas.txt" "$work/pages.txt" "$work/report.tsv" \
  | sort -u > "$work/failures.txt"
cat "$work/failures.txt"
failures=$((failures + $(wc -l < "$work/failures.txt")))

# The search box finds "Eq. (16)": the results page of its index letter lists Eq. (16)'s page.
index=$(cd "$html/search" && grep -l "tests_eq16.html" all_*.js | head -1)
if [[ -z $index ]]; then
  fail "search: no search index entry for Eq. (16)"
else
  "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --disable-extensions --allow-file-access-from-files \
    --user-data-dir="$(mktemp -d "$work/profile.XXXX")" --virtual-time-budget=5000 \
    --dump-dom "file://$html/search/${index%.js}.html?Eq.%20(16)" > "$work/search.dom" 2> /dev/null
  grep -q 'style="display: block;"><div class="SREntry"[^>]*><a [^>]*href="../tests_eq16.html"' "$work/search.dom" \
    || fail "search: typing \"Eq. (16)\" in the search box does not list the page of Eq. (16)"
fi

total=$(( $(date +%s) - start ))
echo "docs_browser: ${#pages[@]} pages opened in Chromium in ${browser_seconds} s; make docs took ${docs_seconds} s, the whole check ${total} s"
if (( failures > 0 )); then
  echo "docs_browser: $failures problems"
  exit 1
fi
echo "docs_browser: every formula rendered, every link resolves"
