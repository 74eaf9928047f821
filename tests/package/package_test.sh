#!/usr/bin/env bash
# The Debian package end to end: build it with CPack, install it with apt-get, run what it
# installed from /usr/bin, validate its desktop entry and AppStream metadata, run lintian on it,
# and remove it. It installs into the system, so it runs only as root with apt-get (a CI
# container, a throwaway machine) and skips otherwise.
#   package_test.sh BUILD_DIR
set -euo pipefail
build=$1
skip() {
    echo "SKIP: $*"
    exit 77 # ctest's SKIP_RETURN_CODE for this test
}
[[ $(id -u) -eq 0 ]] || skip "installs a package into the system: run as root (e.g. in CI)"
command -v apt-get >/dev/null || skip "apt-get is not available"
for tool in cpack dpkg-deb dpkg-parsechangelog dpkg-shlibdeps lintian appstreamcli \
    desktop-file-validate; do
    command -v "$tool" >/dev/null || {
        echo "FAIL: $tool is missing (quickstart.sh lists the package that has it)"
        exit 1
    }
done
package=gnss-workbench
app_id=io.github.gnss_workbench.GnssWorkbench
if dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    skip "$package is already installed here; this test would replace and then remove it"
fi

work=$(mktemp -d)
chmod 755 "$work" # apt's sandbox user reads the .deb from here
installed=0
cleanup() {
    if ((installed)); then
        DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq "$package" >/dev/null 2>&1 ||
            echo "WARNING: could not remove $package"
    fi
    rm -rf "$work"
}
trap cleanup EXIT
failures=0
check() { # check WHAT COMMAND...: runs it, reports, counts a failure
    local what=$1
    shift
    if "$@"; then
        echo "ok: $what"
    else
        echo "FAIL: $what"
        failures=$((failures + 1))
    fi
}

echo "== cpack -G DEB"
(cd "$build" && cpack -G DEB -B "$work" --config CPackConfig.cmake)
deb=$(find "$work" -maxdepth 1 -name "${package}_*.deb" | head -n 1)
[[ -n $deb ]] || {
    echo "FAIL: cpack made no .deb"
    exit 1
}
echo "== $(basename "$deb")"
dpkg-deb --info "$deb" | sed -n '/Package:/,$p'

echo "== control fields"
field() { dpkg-deb --field "$deb" "$1"; }
check "Section is electronics" test "$(field Section)" = electronics
check "Priority is optional" test "$(field Priority)" = optional
check "Maintainer is a name and an address" grep -Eq '^[^<]+ <[^@ ]+@[^> ]+>$' <<<"$(field Maintainer)"
check "Depends computed from the libraries (Qt, libc)" \
    grep -Eq 'libc6 .*libqt6core6|libqt6core6.*libc6' <<<"$(field Depends)"
check "a synopsis and an extended description" test "$(field Description | wc -l)" -gt 3
version=$(field Version)
changelog_version=$(dpkg-deb --fsys-tarfile "$deb" |
    tar -xOf - "./usr/share/doc/$package/changelog.Debian.gz" | gunzip |
    dpkg-parsechangelog -l- -S Version)
check "changelog.Debian.gz is for $version" test "$changelog_version" = "$version"

echo "== apt-get install"
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$deb"
installed=1

echo "== installed files"
for f in /usr/bin/gnss-workbench /usr/bin/gnss-cli /usr/bin/gnss-sim \
    /usr/share/applications/$app_id.desktop /usr/share/metainfo/$app_id.metainfo.xml \
    /usr/share/icons/hicolor/scalable/apps/$app_id.svg \
    /usr/share/man/man1/gnss-workbench.1.gz /usr/share/man/man1/gnss-cli.1.gz \
    /usr/share/man/man1/gnss-sim.1.gz \
    /usr/share/bash-completion/completions/gnss-cli \
    /usr/share/bash-completion/completions/gnss-sim \
    /usr/share/doc/$package/changelog.Debian.gz /usr/share/doc/$package/copyright; do
    check "$f" test -s "$f"
done
# A PNG's width and height: big-endian in its IHDR chunk, bytes 16 to 23.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{ print $3 * 256 + $4 "x" $7 * 256 + $8 }'; }
for size in 16 22 24 32 48 64 128 256; do
    png=/usr/share/icons/hicolor/${size}x${size}/apps/$app_id.png
    check "$png is ${size}x$size" test "$(png_size "$png" 2>/dev/null)" = "${size}x$size"
done

echo "== the programs, from /usr/bin"
upstream=${version%-*}
# No display: --version must not need one.
check "gnss-workbench --version" test "$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM \
    /usr/bin/gnss-workbench --version 2>/dev/null)" = "gnss-workbench $upstream"
check "gnss-cli --version" test "$(/usr/bin/gnss-cli --version)" = "gnss-cli $upstream"
check "gnss-sim --version" test "$(/usr/bin/gnss-sim --version)" = "gnss-sim $upstream"
# shellcheck disable=SC2016 # a sentence, not an expansion
decoded=$(printf '%s\r\n' \
    '$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,0014.4,M,000.6,0100*46' |
    /usr/bin/gnss-cli decode)
echo "$decoded"
check "gnss-cli decode of a typed GGA" grep -q '"type":"GGA".*"quality":4' <<<"$decoded"

for program in gnss-cli gnss-sim; do
    check "bash completion for $program loads" bash -c \
        "source /usr/share/bash-completion/completions/$program && complete -p $program >/dev/null"
done

echo "== desktop-file-validate"
check "desktop entry" desktop-file-validate "/usr/share/applications/$app_id.desktop"
echo "== appstreamcli validate --no-net"
check "AppStream metainfo" appstreamcli validate --no-net "/usr/share/metainfo/$app_id.metainfo.xml"
echo "== lintian"
check "lintian: no errors" lintian --fail-on error --display-info "$deb"

if ((failures > 0)); then
    echo "$failures package check(s) failed"
    exit 1
fi
echo "package built, installed, checked and removed"
