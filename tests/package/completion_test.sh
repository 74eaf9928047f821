#!/usr/bin/env bash
# The bash completions (packaging/completion) offer what the programs accept: every gnss-cli
# command, each command's options exactly as `gnss-cli COMMAND --help` lists them, gnss-sim's
# options as `gnss-sim --help` lists them, dialects, setting keys and files.
#   completion_test.sh GNSS_CLI GNSS_SIM COMPLETION_DIR
set -euo pipefail
cli=$1 sim=$2 dir=$3
# shellcheck source=/dev/null
source "$dir/gnss-cli"
# shellcheck source=/dev/null
source "$dir/gnss-sim"
failures=0

# complete FUNCTION WORD... : what FUNCTION offers for the last WORD, sorted, one per line.
complete_words() {
    local fn=$1
    shift
    COMP_WORDS=("$@")
    COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
    COMP_LINE="${COMP_WORDS[*]}"
    COMP_POINT=${#COMP_LINE}
    COMPREPLY=()
    "$fn" 2>/dev/null
    printf '%s\n' "${COMPREPLY[@]}" | sed '/^$/d' | sort
}

expect() { # expect WHAT EXPECTED ACTUAL
    if [[ "$2" != "$3" ]]; then
        echo "FAIL: $1"
        diff <(echo "$2") <(echo "$3") | sed 's/^/    /' || true
        failures=$((failures + 1))
    else
        echo "ok: $1"
    fi
}

contains() { # contains WHAT NEEDLE HAYSTACK
    if grep -qxF -- "$2" <<<"$3"; then
        echo "ok: $1"
    else
        echo "FAIL: $1: '$2' not offered; got:"
        printf '    %s\n' "$3"
        failures=$((failures + 1))
    fi
}

# Option names as a --help lists them ("  --name VALUE  help" or "  -h, --help  help").
listed_options() { sed -n 's/^  \(-[a-zA-Z], \)\{0,1\}\(--[a-z0-9-]*\).*/\2/p' | sort -u; }

mapfile -t commands < <("$cli" --help | sed -n '/^commands:/,/^$/p' |
    sed -n 's/^  \([a-z][a-z]*\).*/\1/p' | sort -u)
((${#commands[@]} > 0)) || { echo "FAIL: no commands in gnss-cli --help"; exit 1; }
expect "gnss-cli commands" "$(printf '%s\n' "${commands[@]}" help --help --version --list-dialects | sort)" \
    "$(complete_words _gnss_cli "$cli" "")"

for c in "${commands[@]}"; do
    expect "gnss-cli $c options" "$("$cli" "$c" --help | sed -n '/^options:/,$p' | listed_options)" \
        "$(complete_words _gnss_cli "$cli" "$c" --)"
done

# The dialects are the program's registry's (gnss-cli --list-dialects), never a list kept here.
known=$("$cli" --list-dialects | cut -f1 | sort)
simulated=$("$cli" --list-dialects | awk -F'\t' '$2 == "sim" { print $1 }' | sort)
[[ $(wc -l <<<"$known") -ge 2 && -n $simulated ]] ||
    { echo "FAIL: gnss-cli --list-dialects lists no dialects"; exit 1; }
dialects=$(printf '%s\n' auto $known | sort)
expect "--dialect values" "$dialects" "$(complete_words _gnss_cli "$cli" decode --dialect "")"
expect "--dialect=n (split at =)" "$(grep '^n' <<<"$known")" \
    "$(complete_words _gnss_cli "$cli" monitor --dialect = n)"
expect "--dialect=n (whole word)" "$(grep '^n' <<<"$known" | sed 's/^/--dialect=/')" \
    "$(complete_words _gnss_cli "$cli" stats --dialect=n)"
expect "config --sim values" "$simulated" \
    "$(complete_words _gnss_cli "$cli" config --sim "")"
expect "schema DIALECT" "$known" \
    "$(complete_words _gnss_cli "$cli" schema "")"
expect "help COMMAND" "$(printf '%s\n' "${commands[@]}")" "$(complete_words _gnss_cli "$cli" help "")"
expect "config actions" "$(printf '%s\n' action apply diff export get set)" \
    "$(complete_words _gnss_cli "$cli" config --sim nvs "")"
expect "config action what" "$(printf '%s\n' cold defaults hot save warm)" \
    "$(complete_words _gnss_cli "$cli" config --port=/dev/ttyUSB0 action "")"
contains "encode keys from the schema" "rtk.PVTRATE" \
    "$(complete_words _gnss_cli "$cli" encode nvs rtk.P)"
contains "config get keys of --sim's dialect" "nav.ELEV" \
    "$(complete_words _gnss_cli "$cli" config --sim geostar --baud 9600 get nav.E)"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
touch "$tmp/a log.nmea" "$tmp/b.nmea"
expect "decode FILE, a name with a space kept whole" \
    "$(printf '%s\n' "$tmp/a log.nmea" "$tmp/b.nmea")" \
    "$(complete_words _gnss_cli "$cli" decode --lenient "$tmp/")"
expect "--replay FILE" "$tmp/b.nmea" "$(complete_words _gnss_cli "$cli" monitor --replay "$tmp/b")"

expect "gnss-sim options" "$("$sim" --help | listed_options)" \
    "$(complete_words _gnss_sim "$sim" --)"
expect "gnss-sim --dialect" "$("$sim" --list-dialects | cut -f1 | sort)" \
    "$(complete_words _gnss_sim "$sim" --dialect "")"
expect "gnss-sim --dialect=g (whole word)" "--dialect=geostar" \
    "$(complete_words _gnss_sim "$sim" --pty --dialect=g)"

if ((failures > 0)); then
    echo "$failures completion check(s) failed"
    exit 1
fi
