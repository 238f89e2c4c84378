#!/usr/bin/env bash
# Usage: hostile_case.sh CASE ACANTHUS PROGRAM SOURCE_DIR
# One case of the hostile corpus (tests/hostile/CMakeLists.txt): a hostile input or a runaway
# rule against `acanthus` or the generated program PROGRAM (built from runaway.acr). Each case
# checks the exit status, the message, that it took seconds (not minutes), that no output file
# was left behind and that no input changed.
set -u
case_name="$1"
acanthus="$2"
program="$3"
here="$4"
tmp="$(mktemp -d)"
work="$tmp/w"
mkdir "$work"
trap 'rm -rf "$tmp"' EXIT
cd "$work" || exit 1
fail() {
  echo "FAIL: $case_name: $*"
  exit 1
}

# Every file under the work directory with its type, size and checksum: what "unchanged" means.
snapshot() {
  find . -mindepth 1 -printf '%p %y %s\n' | sort
  find . -type f -exec md5sum {} + | sort
}

# expect STATUS REGEX MAX_SECONDS COMMAND...: runs COMMAND in the work directory (an empty
# REGEX expects nothing in particular on stderr).
expect() {
  local want="$1" regex="$2" max="$3"
  shift 3
  snapshot >"$tmp/before"
  local start end rc
  start=$(date +%s%N)
  timeout -k 5 $((max + 30)) "$@" >"$tmp/out" 2>"$tmp/err" </dev/null
  rc=$?
  end=$(date +%s%N)
  local ms=$(((end - start) / 1000000))
  echo "exit $rc after ${ms} ms; stderr:"
  head -c 2000 "$tmp/err"
  [ "$rc" -eq "$want" ] || fail "exit status $rc, expected $want"
  [ -z "$regex" ] || grep -Eq -- "$regex" "$tmp/err" || fail "stderr does not match '$regex'"
  [ "$ms" -le $((max * 1000)) ] || fail "took ${ms} ms, more than ${max} s"
  snapshot >"$tmp/after"
  if ! cmp -s "$tmp/before" "$tmp/after"; then
    diff "$tmp/before" "$tmp/after"
    fail "the work directory changed (an output left behind or an input changed)"
  fi
}

rules() { cp "$here/runaway.acr" "$work/x.acr"; }
panel() { printf '<svg xmlns="http://www.w3.org/2000/svg"><rect width="100" height="80"/></svg>\n' >panel.svg; }
all_outputs=(-o out.svg --json tree.json --frames frames --every 1 --debug-frame 1 debug.png)

case "$case_name" in
  # --- inputs that are not regular files, or too large -------------------------------------------
  region_dev_zero) expect 1 "/dev/zero.*not a regular file" 5 "$program" --region /dev/zero -o out.svg ;;
  check_dev_zero) expect 1 "/dev/zero.*not a regular file" 5 "$acanthus" check /dev/zero ;;
  stroke_device)
    ln -s /dev/zero zero.svg
    expect 1 "zero.svg.*not a regular file" 5 "$program" --stroke zero.svg -o out.svg ;;
  region_fifo)
    mkfifo fifo.svg
    expect 1 "fifo.svg.*not a regular file \(a FIFO\)" 5 "$program" --region fifo.svg -o out.svg ;;
  check_fifo)
    mkfifo fifo.acr
    expect 1 "fifo.acr.*not a regular file \(a FIFO\)" 5 "$acanthus" check fifo.acr ;;
  stroke_fifo)
    mkfifo fifo.svg
    expect 1 "fifo.svg.*not a regular file" 5 "$program" --stroke fifo.svg -o out.svg ;;
  import_fifo)
    mkfifo lib.acr
    printf '%%import "lib"\n%%element\nseed point\n%%endelement\n' >main.acr
    expect 1 "lib.acr.*not a regular file" 5 "$acanthus" check main.acr ;;
  region_directory)
    mkdir dir.svg
    expect 1 "dir.svg.*not a regular file \(a directory\)" 5 "$program" --region dir.svg -o out.svg ;;
  region_too_large)
    truncate -s 65M big.svg
    expect 1 "big.svg.*larger than the 64 MiB limit" 5 "$program" --region big.svg -o out.svg ;;
  rules_too_large)
    truncate -s 65M big.acr
    expect 1 "big.acr.*larger than the 64 MiB limit" 5 "$acanthus" check big.acr ;;

  # --- outputs: all or nothing, distinct, never over an input ------------------------------------
  json_unwritable)
    expect 1 "/proc/t.json" 20 "$program" --region rect:60,40 -o out.svg --json /proc/t.json ;;
  metrics_full_stdout)
    [ -w /dev/full ] || { echo "skipped: no /dev/full"; exit 0; }
    snapshot >"$tmp/before"
    timeout 60 "$program" --region rect:60,40 -o out.svg --metrics >/dev/full 2>"$tmp/err"
    rc=$?
    cat "$tmp/err"
    [ "$rc" -eq 1 ] || fail "exit status $rc, expected 1"
    grep -q "stdout" "$tmp/err" || fail "the message does not name stdout"
    snapshot >"$tmp/after"
    cmp -s "$tmp/before" "$tmp/after" || fail "an output was left behind" ;;
  json_same_as_output)
    expect 2 "--json.*same file" 5 "$program" --region rect:60,40 --json out.svg -o out.svg ;;
  json_same_file_other_spelling)
    mkdir sub
    expect 2 "same file" 5 "$program" --region rect:60,40 --json ./sub/../out.svg -o out.svg ;;
  debug_frame_same_as_output)
    expect 2 "same file" 5 "$program" --region rect:60,40 --debug-frame 1 out.png -o out.png ;;
  output_over_region)
    panel
    expect 2 "overwrite.*panel.svg" 5 "$program" --region panel.svg -o panel.svg ;;
  compile_over_input)
    rules
    expect 2 "would overwrite the input" 10 "$acanthus" compile x.acr -o x.acr ;;
  build_over_input)
    rules
    expect 2 "would overwrite the input" 10 "$acanthus" build x.acr -o x.acr ;;
  compile_over_import)
    printf '%%element\nseed point\n%%endelement\n' >lib.acr
    printf '%%import "lib"\n' >main.acr
    expect 2 "would overwrite the input 'lib.acr'" 10 "$acanthus" compile main.acr -o lib.acr ;;

  # --- runaway rule bodies ------------------------------------------------------------------------
  loop_time_limit)
    expect 3 "runaway.acr:[0-9]+: rule 'dot --> dot': still running" 10 \
      "$program" --param mode=1 --time-limit 2 --region rect:200,150 "${all_outputs[@]}" ;;
  loop_call_limit)
    expect 3 "runaway.acr:[0-9]+: rule 'dot --> dot': still running after 1 s" 10 \
      "$program" --param mode=1 --param after=20 --body-time-limit 1 --region rect:200,150 \
      "${all_outputs[@]}" ;;
  loop_default_limit)
    expect 3 "runaway.acr:[0-9]+: rule 'dot --> dot': still running after 10 s" 20 \
      "$program" --param mode=1 --region rect:200,150 -o out.svg ;;
  recursion)
    expect 3 "runaway.acr:[0-9]+: rule 'dot --> dot': crashed: stack overflow" 20 \
      "$program" --param mode=2 --param after=20 --region rect:200,150 "${all_outputs[@]}" ;;
  negative_radius)
    expect 3 "runaway.acr:[0-9]+: rule 'dot --> dot':.*negative radius" 20 \
      "$program" --param mode=3 --param after=20 --region rect:200,150 "${all_outputs[@]}" ;;
  huge_radius)
    expect 3 "runaway.acr:[0-9]+: rule 'dot --> dot':.*radius beyond 1e\+09" 20 \
      "$program" --param mode=4 --region rect:200,150 "${all_outputs[@]}" ;;
  radius_just_beyond_range)
    expect 3 "rule 'dot --> dot':.*radius beyond" 20 \
      "$program" --param mode=6 --region rect:200,150 -o out.svg ;;
  huge_coordinate)
    expect 3 "runaway.acr:[0-9]+: rule 'dot --> dot':.*coordinate beyond" 20 \
      "$program" --param mode=5 --region rect:200,150 "${all_outputs[@]}" ;;

  # --- regions: coordinate range, lib2geom failures, huge boundaries ----------------------------
  region_spec_huge)
    expect 1 "rect:1e300,1e300.*coordinates out of range" 5 "$program" --region rect:1e300,1e300 -o out.svg ;;
  region_path_huge)
    printf '<svg xmlns="http://www.w3.org/2000/svg"><path id="far" d="M0,0 H1e300 V1 Z"/></svg>\n' >far.svg
    expect 1 "far.svg.*far.*coordinates out of range" 5 "$program" --region far.svg -o out.svg ;;
  region_arc_1e88)
    printf '<svg xmlns="http://www.w3.org/2000/svg"><path id="arc" d="M 1e88,0 A 1,1 6 0 0 0,1 Z"/></svg>\n' >arc.svg
    expect 1 "arc.svg.*arc" 5 "$program" --region arc.svg -o out.svg ;;
  region_many_arcs)
    # 100,000 small arcs along one edge (200,000 cubics): loads, seeds and grows in seconds.
    awk 'BEGIN { printf "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"M0,0";
                 for (i = 0; i < 100000; i++) printf " a2,2 0 0 1 1,0";
                 printf " L100000,100 L0,100 Z\"/></svg>\n" }' >arcs.svg
    expect 0 "" 60 "$program" --region arcs.svg --max-elements 300 -o - ;;
  region_too_many_cubics)
    # 100,000 half-circle arcs are 1.2 million cubics: past the limit, refused at once.
    awk 'BEGIN { printf "<svg xmlns=\"http://www.w3.org/2000/svg\"><path id=\"comb\" d=\"M0,0";
                 for (i = 0; i < 100000; i++) printf " a0.5,0.5 0 0 1 1,0";
                 printf " L100000,100 L0,100 Z\"/></svg>\n" }' >arcs.svg
    expect 1 "arcs.svg.*comb.*more than 1000000 curves once arcs become cubic" 30 "$program" --region arcs.svg -o out.svg ;;

  # --- parameters and seeds -----------------------------------------------------------------------
  param_float_overflow) expect 1 "'f'.*out of range for float" 5 "$program" --param f=1e39 -o out.svg ;;
  param_float_underflow) expect 1 "'f'.*out of range for float" 5 "$program" --param f=1e-50 -o out.svg ;;
  param_double_overflow) expect 1 "'d'.*out of range for double" 5 "$program" --param d=1e400 -o out.svg ;;
  param_int_overflow) expect 1 "'mode'.*out of range for int" 5 "$program" --param mode=2147483648 -o out.svg ;;
  param_long_overflow) expect 1 "'n'.*out of range for long" 5 "$program" --param n=9223372036854775808 -o out.svg ;;
  rng_seed_negative) expect 2 "--rng-seed" 5 "$program" --rng-seed -1 -o out.svg ;;
  rng_seed_2_64) expect 2 "--rng-seed" 5 "$program" --rng-seed 18446744073709551616 -o out.svg ;;
  rng_seed_exponent) expect 2 "--rng-seed" 5 "$program" --rng-seed 1e23 -o out.svg ;;

  # --- the compiler's command line and rule files -------------------------------------------------
  unclosed_brace)
    printf '%%element\nseed point\n%%endelement\n%%rule\nseed --> seed\n{\n    if (true) {\n        return FAILURE;\n    return SUCCESS;\n}\n%%endrule\n' >open.acr
    expect 1 "open.acr:7:15: error: unclosed '\{'" 5 "$acanthus" check open.acr ;;
  unknown_command)
    expect 2 "unknown command 'frobnicate'" 5 "$acanthus" frobnicate
    grep -q "compile" "$tmp/err" && grep -q "build" "$tmp/err" || fail "the commands are not listed" ;;
  *) fail "unknown case" ;;
esac
echo "ok: $case_name"
