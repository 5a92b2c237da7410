#!/usr/bin/env bash
# Runs the Khronos glTF validator (npm package gltf-validator) on GLB files.
#   scripts/validate_glb.sh --install       installs it with npm into $GLTF_VALIDATOR_HOME
#                                           (default ~/.cache/garment-studio/gltf-validator)
#   scripts/validate_glb.sh FILE.glb...     prints per file the validator's counts and messages
# Exit 0: every file has 0 errors and 0 warnings; 1: some has errors or warnings; 2: the validator
# (or node) is not installed, which tests/io/test_sewn_export.cpp reports as a skip.
set -euo pipefail
home="${GLTF_VALIDATOR_HOME:-$HOME/.cache/garment-studio/gltf-validator}"
if [[ "${1:-}" == "--install" ]]; then
  mkdir -p "$home"
  npm install --prefix "$home" --no-audit --no-fund gltf-validator
  exit 0
fi
if [[ $# -eq 0 ]]; then
  echo "usage: $0 --install | FILE.glb..." >&2
  exit 2
fi
if ! command -v node >/dev/null || [[ ! -d "$home/node_modules/gltf-validator" ]]; then
  echo "gltf-validator not installed (node and $home/node_modules/gltf-validator needed):" \
    "run $0 --install" >&2
  exit 2
fi
NODE_PATH="$home/node_modules" exec node - "$@" <<'JS'
const fs = require('fs');
const validator = require('gltf-validator');
(async () => {
  let bad = false;
  for (const file of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
    const issues = report.issues;
    console.log(`${file}: validator ${report.validatorVersion}: ${issues.numErrors} errors, ` +
                `${issues.numWarnings} warnings, ${issues.numInfos} infos, ${issues.numHints} hints`);
    for (const message of issues.messages)
      console.log(`  ${message.severity === 0 ? 'error' : message.severity === 1 ? 'warning' :
                   message.severity === 2 ? 'info' : 'hint'} ${message.code} ${message.pointer || ''}: ` +
                  message.message);
    if (issues.numErrors > 0 || issues.numWarnings > 0) bad = true;
  }
  process.exit(bad ? 1 : 0);
})().catch((error) => { console.error(String(error)); process.exit(1); });
JS
