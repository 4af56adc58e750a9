#!/usr/bin/env bash
# Nothing committed carries an absolute path of the machine that made it (results, summaries,
# markdown written by scripts). Usage: no_machine_paths_test.sh SOURCE_DIR
set -euo pipefail
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/../apps/cli_test_lib.sh" root "$@"
src="$ROOT"
git -C "$src" rev-parse >/dev/null 2>&1 || skip "not a git checkout: nothing to check"
# This checkout's own location, and the home and work folders of build machines.
pattern="$(printf '%s' "$src" | sed 's/[.[\*^$]/\\&/g')|/work/|/root/|/home/[a-z]"
hits="$(git -C "$src" ls-files -z | (cd "$src" && xargs -0 grep -I -l -E "$pattern" -- \
  2>/dev/null) | grep -v -E '^tests/docs/no_machine_paths_test\.sh$' || true)"
if [ -n "$hits" ]; then
  echo "FAIL: committed files carry absolute machine paths:"
  (cd "$src" && grep -I -n -E "$pattern" $hits | head -20)
  exit 1
fi
echo "no committed file carries an absolute machine path"
