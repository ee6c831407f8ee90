#!/usr/bin/env bash
# `prism bench`: every suite runs at --quick sizes and prints its tables; bad arguments
# are usage errors. The JSON's structure is checked by bench_cli_test.cpp (nlohmann, no
# jq needed). No timing is asserted: speed targets live in BENCHMARKS.md, never in tests.
# Usage: bench_cli.sh PATH_TO_PRISM.
set -u
prism="$1"
failures=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

if "$prism" bench --list 2>&1 | grep -q "without the bench suites"; then
  echo "bench CLI: skipped (built without bench/)"
  exit 0
fi
suites=$("$prism" bench --list | awk '{print $1}')
[ -n "$suites" ] || fail "bench --list printed no suites"
for expected in limit throughput steadiness convergence sampler display scaling startup efficiency; do
  grep -qx "$expected" <<<"$suites" || fail "bench --list lacks $expected"
done

for suite in $suites; do
  if ! "$prism" bench "$suite" --quick --threads 2 --json "$work/$suite.json" >"$work/out" 2>"$work/err"; then
    fail "bench $suite --quick: $(cat "$work/err")"
    continue
  fi
  grep -q "^## $suite: " "$work/out" || fail "bench $suite: no table heading in the output"
  grep -q "^-\+  -" "$work/out" || fail "bench $suite: no column rule under a table header"
  [ -s "$work/$suite.json" ] || fail "bench $suite: --json wrote nothing"
done

# Two suites in one run print both.
if "$prism" bench scaling steadiness --quick >"$work/out" 2>"$work/err"; then
  grep -q "^## scaling: " "$work/out" && grep -q "^## steadiness: " "$work/out" ||
    fail "bench scaling steadiness: expected both tables"
else
  fail "bench scaling steadiness --quick: $(cat "$work/err")"
fi

# efficiency --scene renders a scene file through its loader (the glossy pbrt-v4 box here).
scenes="$(cd "$(dirname "$0")/../../data/scenes" && pwd)"
if "$prism" bench efficiency --quick --scene "$scenes/cornell-box-glossy.pbrt" >"$work/out" 2>"$work/err"; then
  grep -q "^## efficiency: .*cornell-box-glossy.pbrt 16^2" "$work/out" ||
    fail "bench efficiency --scene: the table does not name the scene: $(head -3 "$work/out")"
else
  fail "bench efficiency --scene cornell-box-glossy.pbrt: $(cat "$work/err")"
fi
# convergence --scene likewise, scoring chromaticity over the whole image.
if "$prism" bench convergence --quick --scene "$scenes/cornell-box.pbrt" >"$work/out" 2>"$work/err"; then
  grep -q "^## convergence: .*cornell-box.pbrt 16^2.*whole-image xy error" "$work/out" ||
    fail "bench convergence --scene: the table does not name the scene and region: $(head -3 "$work/out")"
  grep -q "^cosh-3 " "$work/out" || fail "bench convergence: no cosh-3 row: $(cat "$work/out")"
else
  fail "bench convergence --scene cornell-box.pbrt: $(cat "$work/err")"
fi
# A missing scene file: a one-line error naming it, a non-zero exit.
"$prism" bench efficiency --quick --scene "$work/missing.pbrt" >/dev/null 2>"$work/err"
status=$?
[ "$status" != 0 ] || fail "bench efficiency --scene MISSING: exit 0"
[ "$(wc -l <"$work/err")" = 1 ] && grep -q "missing.pbrt" "$work/err" ||
  fail "bench efficiency --scene MISSING: expected one line naming the file, got: $(cat "$work/err")"

# Usage errors: exit 2 and one line on stderr.
for args in "no-such-suite" "" "limit --quick --full" "limit --repeat 0"; do
  # shellcheck disable=SC2086
  "$prism" bench $args >/dev/null 2>"$work/err"
  status=$?
  [ "$status" = 2 ] || fail "bench $args: exit $status, expected 2"
  [ "$(wc -l <"$work/err")" = 1 ] || fail "bench $args: expected one line on stderr, got: $(cat "$work/err")"
done

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "bench CLI: all checks passed"
