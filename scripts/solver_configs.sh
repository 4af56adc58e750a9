#!/usr/bin/env bash
# A copy of configs/ at DEST whose OCP configs (configs/ocp/*.yaml) all select the linear solver
# SOLVER (mumps or ldl, solver.linear_solver), for measuring one solver against the other:
# scripts/library_throughput.sh. The other folders are links,
# library/ a copy, so every relative path of a config still resolves; configs/ is not written.
# Usage: scripts/solver_configs.sh DEST SOLVER
set -euo pipefail

if [[ $# -ne 2 ]]; then
  echo "usage: $0 DEST SOLVER" >&2
  exit 2
fi
dest="$1"
solver="$2"
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$dest/ocp" "$dest/library"
for d in "$root"/configs/*/; do
  name="$(basename "$d")"
  [[ "$name" == ocp || "$name" == library ]] || ln -s "$d" "$dest/$name"
done
cp "$root"/configs/library/*.yaml "$dest/library/"
/usr/bin/python3 - "$root/configs/ocp" "$dest/ocp" "$solver" <<'PY'
import pathlib, re, sys
source, target, solver = sys.argv[1:]
line = f"solver:\n  linear_solver: {solver}"
for config in pathlib.Path(source).glob("*.yaml"):
    text = config.read_text()
    if re.search(r"^  linear_solver:", text, re.M):  # a config that pins its solver
        text = re.sub(r"^  linear_solver: \w+", f"  linear_solver: {solver}", text, flags=re.M)
    elif re.search(r"^solver:\s*$", text, re.M):
        text = re.sub(r"^solver:\s*$", line, text, count=1, flags=re.M)
    else:
        text += "\n" + line + "\n"
    (pathlib.Path(target) / config.name).write_text(text)
PY
