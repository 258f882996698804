#!/usr/bin/env bash
# The README opens with exactly two set-up commands, and .ci/run runs the
# second one verbatim. Usage: readme_commands.sh SOURCE_DIR
set -euo pipefail
src="$1"
# The first line inside each ```sh block of the README.
mapfile -t cmds < <(awk '/^```sh$/ {getline; print}' "$src/README.md")
if [ "${#cmds[@]}" -lt 2 ]; then
  echo "README.md: expected two set-up commands in sh blocks, found ${#cmds[@]}" >&2
  exit 1
fi
if ! grep -qxF -- "${cmds[1]}" "$src/.ci/run"; then
  echo ".ci/run does not contain the README's test command:" >&2
  echo "  ${cmds[1]}" >&2
  exit 1
fi
echo "README commands and .ci/run agree"
