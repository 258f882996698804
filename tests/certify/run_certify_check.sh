#!/usr/bin/env bash
# kvd certify on one scene, then the independent checker on the certificate
# (it must accept it) and on tampered copies (it must reject each one): those
# of tamper.py, or of tamper_segments.py for a segment scene's certificate.
# usage: run_certify_check.sh KVD PYTHON3 SOURCE_DIR SCENE EVENTS [MUST_APPLY...]
# SCENE is a file, or "generate:ARGS" for the scene `kvd generate ARGS` writes.
# Each MUST_APPLY tampering must apply to the certificate (and be rejected).
# The checker runs as its own executable (Debian's python3 with python3-sympy);
# PYTHON3 runs the tampering script, which needs only the standard library.
set -euo pipefail
kvd=$1 python=$2 src=$3 scene=$4 events=$5
shift 5
must_apply=" $* "
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $scene == generate:* ]]; then
  # shellcheck disable=SC2086 # the generator's arguments, split on purpose
  "$kvd" generate ${scene#generate:} -o "$work/generated.json"
  scene=$work/generated.json
fi
checker=$src/proofs/check-certificate
"$kvd" certify "$scene" --events "$events" --out "$work/cert.json" >/dev/null
"$checker" "$work/cert.json"
tamper=$src/tests/certify/tamper.py
if grep -q '^"format": "kvd-segment-event-order/1",$' "$work/cert.json"; then tamper=$src/tests/certify/tamper_segments.py; fi
applied=0
for t in $("$python" "$tamper" --list); do
  status=0
  "$python" "$tamper" "$work/cert.json" "$t" "$work/$t.json" >/dev/null || status=$?
  if [ "$status" -eq 3 ]; then
    if [[ $must_apply == *" $t "* ]]; then echo "FAIL: $t does not apply to $(basename "$scene")"; exit 1; fi
    echo "$t: not applicable to $(basename "$scene")"
    continue
  fi
  [ "$status" -eq 0 ] || { echo "tamper.py $t failed with status $status"; exit 1; }
  status=0
  "$checker" "$work/$t.json" 2>"$work/why" || status=$?
  if [ "$status" -ne 1 ]; then echo "FAIL: the checker exited $status on the $t tampering"; exit 1; fi
  echo "$t: rejected: $(head -c 300 "$work/why")"
  applied=$((applied + 1))
done
echo "$(basename "$scene"): certificate accepted, $applied tamperings rejected"
