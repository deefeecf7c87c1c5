# Sourced by compare.sh and quality.sh: one POV-Ray render, timed. Needs from the script: here
# (bench/povray), tmp (a scratch directory), width, height, threads, python, die and now_ns.

# povray_render MATERIAL PNG OPTION...: renders bench/povray/MATERIAL.pov to PNG with the options
# (output format and anti-aliasing) at width x height on `threads` threads; prints
# "trace_ms wall_ms": POV-Ray's own Trace Time and the whole process's wall time.
povray_render() {
  local material=$1 png=$2 log="$tmp/povray.log" t0 t1 trace
  shift 2
  rm -f "$png"
  t0=$(now_ns)
  if ! (cd "$tmp" && povray "+L$here" "+I$here/$material.pov" "+O$png" "+W$width" "+H$height" \
          "$@" "+WT$threads" -D -P >"$log" 2>&1); then
    tail -n 20 "$log" >&2
    die "povray failed on $material.pov with $*"
  fi
  t1=$(now_ns)
  [ -s "$png" ] || die "povray wrote no PNG for $material.pov with $*"
  # "  Trace Time:       0 hours  0 minutes  1 seconds (1.234 seconds)"
  trace=$(tr '\r' '\n' <"$log" | sed -n 's/^ *Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' | tail -n 1)
  [ -n "$trace" ] || { tail -n 20 "$log" >&2; die "no Trace Time in POV-Ray's statistics for $material"; }
  "$python" -c "import sys; print(f'{float(sys.argv[1]) * 1000:.3f} {(int(sys.argv[3]) - int(sys.argv[2])) / 1e6:.3f}')" \
    "$trace" "$t0" "$t1"
}
