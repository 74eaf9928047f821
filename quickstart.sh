#!/usr/bin/env bash
# GNSS Workbench quick start for a fresh Debian 12 machine.
#   ./quickstart.sh run   install what is missing, build, start gnss-workbench (simulated receiver)
#   ./quickstart.sh test  install what is missing, build, run the whole test suite headless
# Idempotent: packages already installed are not touched and the build is incremental.
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-run}
shift || true
preset=${GNSS_PRESET:-dev}
[ "${CI:-}" = "true" ] && preset=ci

packages=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev qt6-base-dev-tools libqt6serialport6-dev libqt6charts6-dev
  # Qt6ChartsConfig.cmake needs Qt6OpenGL/OpenGLWidgets; Debian's charts -dev does not pull them.
  libqt6opengl6-dev
  # lupdate/lrelease (translations) and Qt's own Russian strings.
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
  # Qt6Gui's CMake config looks for OpenGL headers (WrapOpenGL).
  libgl-dev
  libbenchmark-dev fonts-dejavu-core
  # The smoke test runs the real binary on an X server: xvfb-run (xvfb) needs xauth.
  xvfb xauth
  # str2str (RTKLIB) is the real NTRIP 1 caster the corrections tests talk to.
  rtklib
  # gpsd: the gpsd source's tests run the real daemon (foreground, 127.0.0.1, a free port, read
  # only) on a simulated receiver; its own socket service on 2947 is not used by them.
  gpsd
  # The Debian package (cpack -G DEB) and its test (tests/package, ctest -L package):
  # dpkg-shlibdeps computes its Depends, dpkg-parsechangelog reads its changelog;
  dpkg-dev
  # appstreamcli validates the AppStream metainfo;
  appstream
  # desktop-file-validate checks the desktop entry;
  desktop-file-utils
  # lintian checks the .deb as Debian does;
  lintian
  # man --warnings checks that the manual pages format cleanly.
  man-db
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" --parallel "$(nproc)"

case "$mode" in
  run)
    # With no arguments, start on the built-in simulated NV08C-RTK.
    [ $# -eq 0 ] && set -- --sim nvs
    exec "build/$preset/app/gui/gnss-workbench" "$@"
    ;;
  test)
    export QT_QPA_PLATFORM=offscreen
    ctest --preset "$preset" "$@"
    ;;
  *)
    echo "usage: $0 run|test" >&2
    exit 2
    ;;
esac
