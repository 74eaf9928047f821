#!/usr/bin/env bash
# The README's screenshots, taken by gnss-workbench itself (--screenshot) on each simulated
# receiver and of the settings form, each on its own Xvfb screen at 1280x800 (a laptop's), from a
# first start (default layout, English). Builds nothing: give it what is built.
#
#   docs/make_screenshots.sh BUILD_DIR|PATH/TO/gnss-workbench [OUT_DIR]
#
# e.g. docs/make_screenshots.sh build/dev  (writes docs/screenshots/*.png). Needs xvfb-run
# (Debian package xvfb). Each picture takes about 15 s.
set -euo pipefail

usage() {
    echo "usage: $0 BUILD_DIR|PATH/TO/gnss-workbench [OUT_DIR]" >&2
    exit 2
}
[[ $# -ge 1 && $# -le 2 ]] || usage
if [[ -d $1 ]]; then
    app=$1/app/gui/gnss-workbench
else
    app=$1
fi
[[ -x $app ]] || {
    echo "$0: no gnss-workbench at $app (build it first: cmake --build --preset dev)" >&2
    exit 1
}
command -v xvfb-run >/dev/null || {
    echo "$0: xvfb-run is missing (apt-get install xvfb xauth)" >&2
    exit 1
}
out=${2:-$(dirname "$0")/screenshots}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# shot NAME ARGS...: one picture, NAME.png, after the views have filled for 12 s.
shot() {
    local name=$1
    shift
    # A first start (no saved layout or connection), at scale 1, in English, on a fresh X server.
    env -u QT_QPA_PLATFORM -u QT_SCALE_FACTOR -u QT_SCREEN_SCALE_FACTORS \
        XDG_CONFIG_HOME="$tmp/$name" HOME="$tmp" LANG=C.UTF-8 LC_ALL=C.UTF-8 LANGUAGE= \
        xvfb-run -a -s "-screen 0 1280x800x24" \
        "$app" "$@" --screenshot "$out/$name.png" --quit-after 12
    echo "$out/$name.png: $(stat -c %s "$out/$name.png") bytes"
}

shot nvs --sim nvs
shot geostar --sim geostar --show-dock info
shot nemerix --sim nemerix --show-dock satellites
shot nmea --sim nmea --show-dock charts
shot settings --sim nvs --show-dock settings

# The log viewer, on a log the simulator writes: 13 minutes of an NV08C-RTK going from no fix to
# RTK fixed, with a 40 s silence and a few wrong checksums (gnss-sim at 100x for 8 s).
sim=$(dirname "$app")/../sim/gnss-sim
[[ -x $sim ]] || sim=$(command -v gnss-sim || true)
if [[ -n $sim ]]; then
    (sleep 9 | timeout 8 "$sim" --dialect nvs --stdout --speed 100 --internal-base \
        --faults silence=40@200,badcs=0.0005 >"$tmp/drive.nmea") || true
    shot logview "$tmp/drive.nmea" --at 10:04:45
fi
