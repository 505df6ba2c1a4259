# The checks of the command-line tests (test_cli.sh, test_benchmark_command_lines.sh),
# sourced by them: counters, and `expect`.
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAILED: $*"; }

# expect CODE PATTERN -- COMMAND...: exit status CODE and stderr+stdout matching
# PATTERN, within 300 s (a hang is a failure, not a stuck CTest run).
expect() {
  local code=$1 pattern=$2; shift 3
  local out status
  out=$(timeout 300 "$@" 2>&1); status=$?
  if [ "$status" -ne "$code" ]; then fail "$* -> exit $status, expected $code: $out"; return; fi
  if [ -n "$pattern" ] && ! grep -qE -- "$pattern" <<<"$out"; then fail "$* -> output lacks '$pattern': $out"; return; fi
  pass
}
