#!/usr/bin/env bash
# The test command: installs the system tools the cross-check tests use (gcc for generated C,
# spin for Promela, berkeley-abc for AIGER),
# then runs the whole test suite in release mode.
set -euo pipefail
cd "$(dirname "$0")/.."
need=()
command -v gcc >/dev/null || need+=(gcc)
command -v spin >/dev/null || need+=(spin)
command -v berkeley-abc >/dev/null || need+=(berkeley-abc)
if [ ${#need[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq "${need[@]}"
fi
exec cargo test --workspace --release "$@"
