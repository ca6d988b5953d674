# Shared by the bench scripts (sourced, not run).

# jsonField FILE KEY: the value of the first `"KEY": value` line of FILE (dynslam's summary.json,
# dynslam-eval's --json), a number or a string without its quotes; empty when absent.
jsonField() { sed -n "s/^ *\"$2\": *\"\{0,1\}\([^\",]*\).*/\1/p" "$1" | head -1; }
