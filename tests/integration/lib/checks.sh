#------------------------------------------------------------------------------
# Sourced by the integration scripts: a temporary directory $tmp (removed on
# exit), and check NAME CONDITION, which prints ok/FAIL and sets $fail.
#------------------------------------------------------------------------------
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
