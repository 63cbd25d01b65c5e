#!/usr/bin/env bash
# The test command: installs the system tools the cross-check tests use (gcc for generated C,
# spin for Promela, berkeley-abc for AIGER, chromium for the studio's browser tests, graphviz
# for `dot --svg`) and the
# studio's end-to-end driver (playwright-core, npm, pinned in crates/studio/e2e/package.json),
# then runs the whole test suite optimised (the `ci` profile of Cargo.toml: release without LTO,
# which builds the many test binaries much faster).
set -euo pipefail
cd "$(dirname "$0")/.."
need=()
command -v gcc >/dev/null || need+=(gcc)
command -v spin >/dev/null || need+=(spin)
command -v berkeley-abc >/dev/null || need+=(berkeley-abc)
command -v chromium >/dev/null || need+=(chromium)
command -v dot >/dev/null || need+=(graphviz)
if [ ${#need[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq "${need[@]}"
fi
if command -v npm >/dev/null && [ ! -d crates/studio/e2e/node_modules/playwright-core ]; then
  (cd crates/studio/e2e && npm ci --no-audit --no-fund --silent)
fi
exec cargo test --workspace --profile ci "$@"
