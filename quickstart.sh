#!/usr/bin/env bash
# GNSS Workbench quick start for a fresh Debian 12 machine.
#   ./quickstart.sh run   install what is missing, build, start gnss-workbench (simulated receiver)
#   ./quickstart.sh test  install what is missing, then build and run the whole suite headless
#                         (with the committed fuzz corpora replayed). GNSS_TEST_STAGES="dev asan
#                         tsan" adds the sanitizer stages: the asan build (AddressSanitizer +
#                         UBSan) and the whole suite, the tsan build (ThreadSanitizer) and the
#                         suites of the threaded code (ctest label tsan). Fails when any stage
#                         fails (a sanitizer finding fails its test); prints each stage's time.
#                         With CI=true (.ci/run) the stages are "ci asan tsan": CI fails on any
#                         sanitizer report (its budget: 45 minutes on 2 cores).
#   ./quickstart.sh fuzz [--fast] SECONDS [HARNESS...]
#                         install clang and libFuzzer too, run tests/fuzz/run.sh
# Idempotent: packages already installed are not touched and the build is incremental.
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-run}
shift || true
preset=${GNSS_PRESET:-dev}
[ "${CI:-}" = "true" ] && preset=ci

packages=(
  build-essential cmake ninja-build pkg-config
  # lld links the test executables several times faster than GNU ld (CI's time budget).
  lld
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev qt6-charts-dev
  # Qt6ChartsConfig.cmake needs Qt6OpenGL/OpenGLWidgets; Debian's charts -dev does not pull them.
  libqt6opengl6-dev
  # lupdate/lrelease (translations) and Qt's own Russian strings.
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
  # Qt6Gui's CMake config looks for OpenGL headers (WrapOpenGL).
  libgl-dev
  libbenchmark-dev fonts-dejavu-core
  # zlib: the log viewer opens .gz logs (inflated on its worker thread).
  zlib1g-dev
  # gpsbabel reads the log viewer's GPX and KML exports back in the tests (they skip without it).
  gpsbabel
  # The smoke test runs the real binary on an X server: xvfb-run (xvfb) needs xauth.
  xvfb xauth
  # A caster's password, when the user asks to keep it, goes to the desktop keychain.
  qtkeychain-qt6-dev
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
  # pdftotext reads the qualification report's PDF back in its tests.
  poppler-utils
)
# The fuzz preset (tests/fuzz): Debian's clang 14 and its libFuzzer.
[ "$mode" = fuzz ] && packages+=(clang-14 libfuzzer-14-dev)

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

case "$mode" in
  run)
    cmake --preset "$preset" >/dev/null
    cmake --build --preset "$preset" --parallel "$(nproc)"
    # With no arguments, start on the built-in simulated NV08C-RTK.
    [ $# -eq 0 ] && set -- --sim nvs
    exec "build/$preset/app/gui/gnss-workbench" "$@"
    ;;
  test)
    export QT_QPA_PLATFORM=offscreen
    # CI runs the sanitizer stages too: a finding fails it.
    default_stages=$preset
    [ "${CI:-}" = "true" ] && default_stages="ci asan tsan"
    stages=${GNSS_TEST_STAGES:-$default_stages}
    summary=()
    failed=0
    for stage in $stages; do
      echo "=== stage $stage: build"
      start=$SECONDS
      status=ok
      if cmake --preset "$stage" >/dev/null &&
        cmake --build --preset "$stage" --parallel "$(nproc)"; then
        built=$((SECONDS - start))
        echo "=== stage $stage: tests"
        ctest --preset "$stage" "$@" || status=FAILED
      else
        built=$((SECONDS - start))
        status="FAILED (build)"
      fi
      [ "$status" = ok ] || failed=1
      line=$(printf '%-5s %-15s build %4d s, tests %4d s, total %4d s' "$stage" "$status" \
        "$built" $((SECONDS - start - built)) $((SECONDS - start)))
      summary+=("$line")
      echo "=== stage $line"
    done
    echo "=== stages (wall time):"
    printf '    %s\n' "${summary[@]}"
    echo "    all   $SECONDS s"
    exit $failed
    ;;
  fuzz)
    exec tests/fuzz/run.sh "$@"
    ;;
  *)
    echo "usage: $0 run|test|fuzz" >&2
    exit 2
    ;;
esac
