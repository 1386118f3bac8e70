#!/usr/bin/env bash
# make docs: the book of the project (Doxygen HTML) in BUILD_DIR/docs/html, from a fresh clone.
#   bash paper/make_docs.sh [BUILD_DIR]     (BUILD_DIR defaults to build)
# 1. installs what is missing (.ci/install-deps.sh: doxygen, libjs-mathjax, gnuplot, ...);
# 2. builds docs_trace and writes with it the page of tests by equation (anchors tests_eq16, tests_eqA5);
# 3. gathers the figures named by `\image html` on paper/*.md: results/figures/NAME.png after
#    `make figures` (results/studies/figures/NAME.png after `make studies`), otherwise a placeholder drawn
#    with gnuplot that says to run them;
# 4. runs Doxygen with paper/Doxyfile, links Debian's MathJax as html/mathjax (nothing from the network);
# 5. fails when Doxygen wrote a single warning (BUILD_DIR/docs/warnings.log).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=$build/docs

bash .ci/install-deps.sh
mkdir -p "$out/generated"
rm -rf "$out/images" "$out/html"
mkdir -p "$out/images"

if [[ ! -f $build/CMakeCache.txt ]]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > "$out/configure.log" 2>&1 || { cat "$out/configure.log"; exit 1; }
fi
cmake --build "$build" --target docs_trace > "$out/build.log" 2>&1 || { cat "$out/build.log"; exit 1; }
# With the mutants of make mutants, when it has been run (results/mutants/mutants.csv).
mutants=(); [[ -f results/mutants/mutants.csv ]] && mutants=(results/mutants/mutants.csv)
"$build/bin/docs_trace" --tests-page "$out/generated/tests_by_equation.md" "${mutants[@]}"

for name in $(sed -n 's/.*\\image html \([A-Za-z0-9_.-]*\).*/\1/p' paper/*.md | sort -u); do
  if [[ -f results/figures/$name ]]; then
    cp "results/figures/$name" "$out/images/$name"
  elif [[ -f results/studies/figures/$name ]]; then  # a figure of make studies
    cp "results/studies/figures/$name" "$out/images/$name"
  else
    stem=${name%.*}
    gnuplot -e "set terminal pngcairo size 900,260 font 'Sans,14'; set output '$out/images/$name';
      unset border; unset tics; unset key; set xrange [0:1]; set yrange [0:1];
      set object 1 rectangle from graph 0.01,0.03 to graph 0.99,0.97 fillstyle empty border lc rgb '#999999' dt 2;
      set label 1 'Figure ${stem//_/\\_} is not made yet.' at graph 0.5,0.62 center font 'Sans,18';
      set label 2 'Run   make figures   and   make studies   (results/), then   make docs   again.' at graph 0.5,0.35 center;
      plot -1 notitle"
  fi
done

{
  cat paper/Doxyfile
  echo "OUTPUT_DIRECTORY = $out"
  echo "WARN_LOGFILE = $out/warnings.log"
  echo "IMAGE_PATH = $out/images"
  echo "INPUT += $out/generated"
} | doxygen - > "$out/doxygen.log" 2>&1 || { cat "$out/doxygen.log"; exit 1; }
ln -sfn /usr/share/javascript/mathjax "$out/html/mathjax"

if [[ -s $out/warnings.log ]]; then
  echo "docs: $(wc -l < "$out/warnings.log") lines of Doxygen warnings ($out/warnings.log):" >&2
  cat "$out/warnings.log" >&2
  exit 1
fi
echo "docs: wrote $out/html/index.html"
