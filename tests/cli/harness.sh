# Shared by the command-line test scripts: a scratch folder, pass/fail counting, and the
# checks every script uses. Source it after setting nothing; call `finish` at the end.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0

check() { # check NAME EXPECTED_CODE COMMAND...: runs COMMAND, stdout/stderr kept in $work
    local name=$1 expected=$2
    shift 2
    "$@" >"$work/stdout" 2>"$work/stderr"
    local code=$?
    if [ "$code" -ne "$expected" ]; then
        echo "FAIL $name: exit $code, expected $expected"; sed 's/^/  /' "$work/stderr" | head -5
        failures=$((failures + 1))
    else
        passes=$((passes + 1))
    fi
}
expect() { # expect NAME CONDITION...
    local name=$1
    shift
    if "$@"; then passes=$((passes + 1)); else echo "FAIL $name"; failures=$((failures + 1)); fi
}
one_line_error() { # one non-empty line on stderr, from wavefront
    [ "$(wc -l <"$work/stderr")" -eq 1 ] && grep -q "^wavefront: " "$work/stderr"
}
json_has() { # json_has FILE PYTHON-EXPRESSION-ON-d
    python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if ($2) else 1)" "$1"
}
finish() {
    echo "$passes passed, $failures failed"
    [ "$failures" -eq 0 ]
}
