#!/usr/bin/env bash
# Builds in Release and measures the engines side by side: prints the table,
# writes it as CSV and plots it (PNG) into ${1:-bench-output}/.
# Options after the folder go to the benchmark (--quick, --no-gpu, --resolution N).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(realpath -m "${1:-$root/bench-output}")"
shift || true
build="$(bash "$root/scripts/build.sh" | tail -n 1)"
mkdir -p "$out"
"$build/bin/BoundParticlesBench" --csv "$out/engines.csv" "$@" | tee "$out/engines.txt"
/usr/bin/python3 "$root/bench/plot.py" "$out/engines.csv" "$out/engines.png"
echo "bench: wrote $out/engines.txt, $out/engines.csv, $out/engines.png"
