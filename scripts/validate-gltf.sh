#!/usr/bin/env bash
# validate-gltf.sh FILE... - checks glTF files with the Khronos glTF validator (npm package
# gltf-validator, installed once into build/gltf-validator/). Prints a line per file and
# every error and warning; exits 1 if any file has errors, 77 if node/npm are missing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$root/build/gltf-validator
if [[ ! -f $dir/node_modules/gltf-validator/package.json ]]; then
    if ! command -v npm >/dev/null; then
        echo "validate-gltf: needs node and npm (Debian: apt-get install nodejs npm)" >&2
        exit 77
    fi
    mkdir -p "$dir"
    npm install --prefix "$dir" --no-audit --no-fund --silent gltf-validator@2.0.0-dev.3.10 >&2 ||
        { echo "validate-gltf: npm could not install gltf-validator" >&2; exit 1; }
fi
exec node "$root/scripts/validate-gltf.cjs" "$dir/node_modules/gltf-validator" "$@"
