#------------------------------------------------------------------------------
# Sourced by the integration scripts: a temporary directory $tmp (removed on
# exit), and check NAME CONDITION, which prints ok/FAIL and sets $fail.
# Every check of a run includes the run's exit status (saved in a variable
# right after it, not read as $? inside the condition) and that the outputs
# it reads exist, so that a crashed run never passes a check.
#------------------------------------------------------------------------------
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
# The exit status of a run that reaches endTime without settling: the one
# place to change when that status changes
unsettledStatus=1
