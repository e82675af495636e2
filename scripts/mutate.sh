#!/usr/bin/env bash
# Mutation test of the test command (issue 13; README, "Does the test command notice wrong
# Verilog?"): does the fast suite notice when the emitted Verilog is wrong? For each of three
# units it edits one operator of hdl-out/ (in the unit's own file and in its copy inside
# raster_top.v), runs the test command's tests (`cargo test --workspace` on the test
# command's build, without lint and synthesis), names every test that failed, and puts the
# files back. A mutation no simulation test catches (hdl_out_is_fresh, which compares
# hdl-out/ with a new emission, catches any edit, and does not count) fails the script.
#
# Each mutation is a plausible slip of hand-written RTL that a weak bench would miss:
#   edge_walk       a colour's step up the edge loses the +1 of its two's complement
#                   (`at + ~inc + up` to `at + ~inc`): one LSB a scanline on upward steps
#   span            the X clip keeps the pixel at x = width (`x >= width` to `x > width`)
#   triangle_setup  the first scanline centre of vertex 0 in setup's geometry (computed
#                   once per triangle, as it is taken, and handed on from copy to copy)
#                   rounds a y on a pixel centre up (`y + half - 1` to `y + half`): the
#                   fill rule's tie
#
# It edits hdl-out/ in place while it runs (the tests read the committed files) and puts it
# back on exit: commit nothing from this tree meanwhile.
#
# `scripts/mutate.sh [UNIT...]` (all three by default) takes about 12 minutes on 2 cores
# after the test command's build; the report is target/mutate/report.md.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-tools.sh
# shellcheck source=scripts/tools-env.sh
source scripts/tools-env.sh
# shellcheck source=scripts/test-build-env.sh
source scripts/test-build-env.sh

out=${CARGO_TARGET_DIR:-target}/mutate
mkdir -p "$out"
saved=$(mktemp -d)
cp hdl-out/*.v "$saved"/
restore() { cp "$saved"/*.v hdl-out/ && rm -rf "$saved"; }
trap restore EXIT

# Four words a mutation: the unit, the module inside the unit's file, the line's text, its
# mutation.
mutations=(
    edge_walk 'edge_walk$cur$c0' 'at_r$d = at_r$q + inc_dir + up;' 'at_r$d = at_r$q + inc_dir;'
    span span 'if (clip_x$on & (x$q >= width_x)) begin' 'if (clip_x$on & (x$q > width_x)) begin'
    triangle_setup 'triangle_setup$geometry' 'cv$0 = ((yn$0 + half_m1) & int_mask) | half;' 'cv$0 = ((yn$0 + half) & int_mask) | half;'
)

# mutate FILE MODULE FROM TO: replaces FROM by TO once, inside module MODULE of FILE.
mutate() {
    awk -v mod="$2" -v from="$3" -v to="$4" '
        /^module / { name = $2; sub(/\(.*/, "", name) }
        !done && name == mod && (i = index($0, from)) {
            $0 = substr($0, 1, i - 1) to substr($0, i + length(from)); done = 1
        }
        { print }
        END { if (!done) { print "no \"" from "\" in module " mod > "/dev/stderr"; exit 1 } }
    ' "$1" >"$1.mutated"
    mv "$1.mutated" "$1"
}

cargo test --workspace --locked "${features[@]}" --no-run
report=$out/report.md
printf '| unit | mutation | tests that failed |\n|---|---|---|\n' >"$report"
survived=0
for ((k = 0; k < ${#mutations[@]}; k += 4)); do
    unit=${mutations[k]} module=${mutations[k + 1]} from=${mutations[k + 2]} to=${mutations[k + 3]}
    [[ $# -eq 0 || " $* " == *" $unit "* ]] || continue
    printf '\n== mutate: %s: %s -> %s\n' "$unit" "$from" "$to"
    cp "$saved"/*.v hdl-out/
    mutate "hdl-out/$unit.v" "$module" "$from" "$to"
    mutate hdl-out/raster_top.v "raster_top\$fragments\$core\$$module" "$from" "$to"
    start=$SECONDS
    cargo test --workspace --locked "${features[@]}" --no-fail-fast >"$out/$unit.log" 2>&1 || true
    failed=$(grep -E '^test .* \.\.\. FAILED$' "$out/$unit.log" | sed -E 's/^test (.*) \.\.\. FAILED$/\1/' | sort -u)
    caught=$(grep -v -x 'emit::hdl_out_is_fresh' <<<"$failed" || true)
    printf '%s\n(%d s; the log: %s)\n' "${failed:-no test failed}" $((SECONDS - start)) "$out/$unit.log"
    printf '| %s | `%s` to `%s` | %s |\n' "$unit" "${from//|/\\|}" "${to//|/\\|}" "$(tr '\n' ' ' <<<"$failed")" >>"$report"
    [[ -n $caught ]] || { echo "the mutation of $unit survived every simulation test" >&2; survived=1; }
done
cat "$report"
exit $survived
