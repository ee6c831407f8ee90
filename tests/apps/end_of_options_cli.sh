#!/usr/bin/env bash
# POSIX's end of options (XBD 12.2, guideline 10) in every subcommand: after `--`, each
# argument is an operand even if it begins with '-'. And `prism` with no arguments prints
# its help (it used to render into the current folder).
# Usage: end_of_options_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# same_output "ARGS A" "ARGS B": both exit 0 with the same stdout.
same_output() {
  local a b
  a=$(cd "$work" && $1 2>&1) || fail "'$1' exited non-zero: $a"
  b=$(cd "$work" && $2 2>&1) || fail "'$2' exited non-zero: $b"
  [ "$a" = "$b" ] || fail "'$1' printed '$a' but '$2' printed '$b'"
}

# expect_usage_error PATTERN ARGS...: exit 2, one stderr line "prism: error: ...PATTERN".
expect_usage_error() {
  local pattern="$1"; shift
  (cd "$work" && "$prism" "$@") >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  [ "$rc" -eq 2 ] || fail "'$*': exit $rc, expected 2 ($(cat "$work/stderr"))"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "'$*': stderr is not one line: $(cat "$work/stderr")"
  grep -q "^prism: error: .*$pattern" "$work/stderr" || fail "'$*': stderr '$(cat "$work/stderr")' lacks '$pattern'"
}

# `prism` alone: the help on stdout, exit 0, and nothing written.
mkdir "$work/empty"
out=$(cd "$work/empty" && "$prism" 2>"$work/stderr"); rc=$?
[ "$rc" -eq 0 ] || fail "prism with no arguments: exit $rc"
grep -q "^Subcommands:" <<<"$out" || fail "prism with no arguments printed no help: $out"
[ "$out" = "$("$prism" --help)" ] || fail "prism with no arguments is not prism --help"
[ -z "$(ls -A "$work/empty")" ] || fail "prism with no arguments wrote $(ls -A "$work/empty")"
expect_usage_error "no subcommand given" --

# color convert: the issue's command, and the same with the numbers as they are.
same_output "$prism color convert --from acescg --to srgb -- -0.1 0.2 0.3" \
            "$prism color convert --from acescg --to srgb -0.1 0.2 0.3"
expect_usage_error "" color convert -- 1 0.5 0.25 --from acescg --to srgb
expect_usage_error "--from is required" color convert -- -0.1 0.2 0.3
expect_usage_error "rgb: At least 3 required" color convert --from srgb --to srgb -- 1 2
expect_usage_error "rgb: At Most 3 required but received 4" color convert --from srgb --to srgb -- 1 2 3 4
same_output "$prism color convert --from acescg --to srgb 0.2 -- -0.1 0.3" \
            "$prism color convert --from acescg --to srgb 0.2 -0.1 0.3"  # operands on both sides
same_output "$prism color spectrum -- 0.5 0.25 0.125" "$prism color spectrum 0.5 0.25 0.125"
expect_usage_error "output needs its value before" render cornell-box -o -- x.exr
expect_usage_error "not expected: 1" color spaces -- 1

# merge: inputs whose names begin with '-', all after `--`, or some before it (CLI11 alone
# ends the subcommand at such a `--` and rejects the rest).
(cd "$work" && "$prism" render cornell-box --width 8 --height 8 --sample-range 0:2 -o ./-a.exr >/dev/null 2>&1 &&
  "$prism" render cornell-box --width 8 --height 8 --sample-range 2:4 -o ./-b.exr >/dev/null 2>&1) ||
  fail "rendering the parts to merge"
(cd "$work" && "$prism" merge -o m1.exr -- -a.exr -b.exr >/dev/null 2>&1) || fail "merge -o m1.exr -- -a.exr -b.exr"
(cd "$work" && "$prism" merge -o m2.exr ./-a.exr -- -b.exr >/dev/null 2>&1) || fail "merge -o m2.exr ./-a.exr -- -b.exr"
[ -s "$work/m1.exr" ] && cmp -s "$work/m1.exr" "$work/m2.exr" || fail "merge with inputs before and after -- differ"
expect_usage_error "" merge -- -a.exr -b.exr -o m3.exr  # -o is an input after --
[ ! -e "$work/m3.exr" ] || fail "merge read -o after -- as an option"

# tonemap and render take their one operand after `--`.
(cd "$work" && "$prism" tonemap -o ./-m.png -- -a.exr >/dev/null 2>&1) || fail "tonemap -o ./-m.png -- -a.exr"
[ -s "$work/-m.png" ] || fail "tonemap -- wrote nothing"
(cd "$work" && "$prism" render --spp 1 --width 8 --height 8 -o r.exr -- cornell-box >/dev/null 2>&1) ||
  fail "render ... -- cornell-box"
[ -s "$work/r.exr" ] || fail "render -- wrote nothing"
# After `--`, --help is an operand, not a request for help: here a scene that does not exist.
expect_usage_error "unknown scene '--help'" info -- --help

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "end of options CLI: all checks passed"
