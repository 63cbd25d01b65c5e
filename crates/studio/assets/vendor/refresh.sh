#!/usr/bin/env bash
# Refresh the vendored layout library at its pinned version, checking both the package and the
# file against the checksums recorded here. Run from anywhere; needs npm (registry access).
# The files are committed: building statecheck never runs npm.
set -euo pipefail
cd "$(dirname "$0")"
VERSION=0.12.1
TGZ_SHA256=7a017dd56e31e4963ad5c4b9deb3230db5c37edf53a82dc507a8599f2f01122f
JS_SHA256=b1032b7cfd2a57c54c6f0e8369d7665e19a579954f7cd20a6dae28f1912ea0d7
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm pack "elkjs@$VERSION" >/dev/null)
echo "$TGZ_SHA256  $tmp/elkjs-$VERSION.tgz" | sha256sum -c -
tar xzf "$tmp/elkjs-$VERSION.tgz" -C "$tmp"
echo "$JS_SHA256  $tmp/package/lib/elk.bundled.js" | sha256sum -c -
cp "$tmp/package/lib/elk.bundled.js" elk.bundled.js
cp "$tmp/package/LICENSE.md" elkjs-LICENSE.md
echo "elkjs $VERSION refreshed"
