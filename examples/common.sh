# Sourced by the examples: paths to the binary, the real data and outputs.
set -euo pipefail
cd "$(dirname "$0")/.."
PFDM=${PFDM:-./build/pfdm}
DATA=${PFDM_DATA:-../shared/data}
OUT=${PFDM_OUT:-out/examples}
if [ ! -x "$PFDM" ]; then
  echo "build pfdm first (./scripts/setup.sh); looked for $PFDM" >&2
  exit 1
fi
if [ ! -d "$DATA" ]; then
  echo "real data folder $DATA is absent (it sits beside the clone)" >&2
  exit 1
fi
mkdir -p "$OUT"
