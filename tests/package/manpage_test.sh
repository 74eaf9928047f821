#!/usr/bin/env bash
# The manual pages (packaging/man) describe what the programs accept: every option each
# program's --help lists (for gnss-cli, every command's), and every gnss-cli command under its
# own heading; and man(1) formats them without a warning (lintian runs the same check).
#   manpage_test.sh MAN_DIR GNSS_CLI GNSS_SIM [GNSS_WORKBENCH]
set -euo pipefail
man_dir=$1 cli=$2 sim=$3 gui=${4:-}
failures=0
fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

# Option names as a --help lists them: "  --name VALUE", "  -h, --help", "  -p, --port <port>".
listed_options() { sed -n 's/^  \(-[a-zA-Z], \)\{0,1\}\(--[a-z0-9-]*\).*/\2/p' | sort -u; }

# check_options PAGE: every option on standard input has an item of its own in PAGE: the line
# after a .TP names it (as \-\-name), not just a mention in an example.
check_options() {
    local page=$1 option items
    items=$(awk 'tp { print; tp = 0 } /^\.TP/ { tp = 1 }' "$page")
    while read -r option; do
        grep -qF -- "${option//-/\\-}" <<<"$items" || fail "$(basename "$page"): $option has no item"
    done
}

mapfile -t commands < <("$cli" --help | sed -n '/^commands:/,/^$/p' |
    sed -n 's/^  \([a-z][a-z]*\).*/\1/p' | sort -u)
((${#commands[@]} > 0)) || fail "no commands in gnss-cli --help"
for c in "${commands[@]}"; do
    grep -q "^\.SS \"${c}[ \"]" "$man_dir/gnss-cli.1" || fail "gnss-cli.1: no section for $c"
done
check_options "$man_dir/gnss-cli.1" < <(for c in "${commands[@]}"; do
    "$cli" "$c" --help | sed -n '/^options:/,$p' | listed_options
done | sort -u)
check_options "$man_dir/gnss-sim.1" < <("$sim" --help | listed_options)
if [[ -n $gui ]]; then
    # --help needs no display; Qt's own options (--help-all lists them) are Qt's to document.
    check_options "$man_dir/gnss-workbench.1" < <(env -u DISPLAY -u WAYLAND_DISPLAY \
        QT_QPA_PLATFORM=offscreen "$gui" --help 2>/dev/null | listed_options)
fi

# Exit codes: each page has the section.
for page in "$man_dir"/*.1; do
    grep -q '^\.SH EXIT STATUS' "$page" || fail "$(basename "$page"): no EXIT STATUS section"
done

if command -v man >/dev/null; then
    for page in "$man_dir"/*.1; do
        warnings=$(LC_ALL=C.UTF-8 MANROFFSEQ='' MANWIDTH=80 man --warnings -E UTF-8 -l -Tutf8 -Z \
            "$page" 2>&1 >/dev/null) || fail "$(basename "$page"): man failed"
        [[ -z $warnings ]] || fail "$(basename "$page"): $warnings"
    done
else
    echo "man is not installed: formatting not checked"
fi

if ((failures > 0)); then
    echo "$failures manual page check(s) failed"
    exit 1
fi
echo "manual pages describe every option and command"
