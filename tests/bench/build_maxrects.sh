#!/usr/bin/env bash
# npm's maxrects-packer (MIT), the plain MaxRects column of tests/bench/saw_benchmark.py, into FOLDER/node_modules.
# Benchmark only: never installed by `make`. Needs Debian's nodejs and npm and the npm registry.
#   tests/bench/build_maxrects.sh FOLDER
set -euo pipefail
folder=${1:?usage: build_maxrects.sh FOLDER}
command -v npm >/dev/null || { sudo=""; [ "$(id -u)" -eq 0 ] || sudo=sudo; $sudo apt-get install -y -qq nodejs npm; }
mkdir -p "$folder"
npm install --prefix "$folder" --no-audit --no-fund maxrects-packer@2.7.4 >/dev/null
echo "maxrects-packer in $folder/node_modules"
