#!/usr/bin/env bash
# What glint reports on stdout (the help, the version, --check,
# --print-scene) and on stderr (their problems, the flags' errors) is its
# result: when it cannot be written in whole, to a full disk or a pipe
# whose reader has gone, glint exits with 3 and says why on stderr, never 0
# with the report lost and never killed by SIGPIPE (141).
# Usage: reports.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"

printf 'materials: { m: {} }\nobjects:\n  - { type: sphere, radius: 1, material: m }\n' >good.yaml
printf 'materials: { m: {} }\nobjects:\n  - { type: sphere, radius: -1, material: m }\n' >bad.yaml

# A pipe with no reader left: every write to it fails with EPIPE.
exec {dead}> >(:)
wait $!

# expect WHAT CODE STDERR OUT GLINT-ARGS...: runs glint with its stdout to
# the file OUT (or to the closed pipe for "dead") and checks its exit code
# and its whole stderr.
expect() {
    local what=$1 code=$2 message=$3 out=$4
    shift 4
    if [ "$out" = dead ]; then
        "$GLINT" "$@" >&"$dead" 2>err.txt
    else
        "$GLINT" "$@" >"$out" 2>err.txt
    fi
    local status=$?
    [ "$status" -eq "$code" ] && [ "$(cat err.txt)" = "$message" ]
    verdict $? "$what: exit $status (expected $code), stderr '$(cat err.txt)'"
}

full="glint: cannot write '<stdout>': No space left on device"
gone="glint: cannot write '<stdout>': Broken pipe"
expect "--help into /dev/full" 3 "$full" /dev/full --help
expect "--version into /dev/full" 3 "$full" /dev/full --version
expect "--check into /dev/full" 3 "$full" /dev/full --check good.yaml
expect "--check of two into /dev/full" 3 "$full" /dev/full --check good.yaml good.yaml
expect "--print-scene into /dev/full" 3 "glint: the scene could not be written" /dev/full --print-scene good.yaml
expect "--help into a closed pipe" 3 "$gone" dead --help
expect "--check into a closed pipe" 3 "$gone" dead --check good.yaml
# A lost report outranks an invalid scene (1), as --check's worst code wins.
expect "--check of a valid and an invalid scene into /dev/full" 3 \
    "$(printf '%s\n%s\n%s' "bad.yaml:3:29: 'radius' must be positive, got -1" \
        "glint: bad.yaml: 1 problem; not valid" "$full")" /dev/full --check good.yaml bad.yaml

# The same reports written in whole: exit 0 (1 for the invalid scene).
expect "--help into a file" 0 "" help.txt --help
check "--help wrote the help" grep -q -- '--version' help.txt
expect "--check into a file" 0 "" check.txt --check good.yaml
check "--check wrote its line" grep -q '^good.yaml: ok: ' check.txt

# stderr closed: the problems or the error are lost, so exit 3, not SIGPIPE.
"$GLINT" --bogus 2>&"$dead"
status=$?
verdict $((status != 3)) "an unknown flag with stderr closed: exit $status, expected 3"
"$GLINT" --check bad.yaml 2>&"$dead" >/dev/null
status=$?
verdict $((status != 3)) "--check of an invalid scene with stderr closed: exit $status, expected 3"
"$GLINT" --check good.yaml 2>&"$dead" >/dev/null
status=$?
verdict $((status != 0)) "--check of a valid scene with stderr closed (nothing to say): exit $status, expected 0"

finish
