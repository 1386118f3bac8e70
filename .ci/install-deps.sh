#!/usr/bin/env bash
# Installs the Debian packages this project needs, and nothing else.
#   .ci/install-deps.sh          install what is missing (apt-get update first), as root or through sudo
#   .ci/install-deps.sh --check  exit 0 if everything is present, 1 otherwise; prints nothing
# When everything is already present it is quick and quiet.
set -euo pipefail

packages=(cmake make g++ libeigen3-dev doctest-dev libgsl-dev libtomlplusplus-dev libmuparser-dev libcli11-dev gnuplot-nox doxygen libjs-mathjax time chromium valgrind)

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done

if [[ "${1:-}" == "--check" ]]; then
  [[ ${#missing[@]} -eq 0 ]]
  exit
fi
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
if [[ $(id -u) -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  as_root=(sudo)
else
  echo "install-deps: need root to install packages; run:" >&2
  echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done" >&2
