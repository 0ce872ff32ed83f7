#!/usr/bin/env bash
# Builds in Release and prints the CPU engine's speed table. Pass --quick for
# the 4096-element column only.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(bash "$root/scripts/build.sh" | tail -n 1)"
"$build/bin/BoundParticlesBench" "$@"
