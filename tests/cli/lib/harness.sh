# harness.sh - what a command-line test shares, sourced first: glint's path
# from the test's first argument, a fresh working directory (removed at
# exit) as the current one, and the count of checks passed and failed.
set -u
GLINT=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
passed=0
failed=0

# verdict STATUS WHAT: a check passes when STATUS is 0, else WHAT is shown.
verdict() {
    if [ "$1" -eq 0 ]; then
        passed=$((passed + 1))
    else
        echo "FAIL: $2"
        failed=$((failed + 1))
    fi
}

# check WHAT COMMAND...: passes when the command succeeds.
check() {
    local what=$1
    shift
    "$@"
    verdict $? "$what"
}

# finish: the counts, and the test's exit status.
finish() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
