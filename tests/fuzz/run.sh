#!/usr/bin/env bash
# Runs the libFuzzer targets built by the fuzz preset, one after another.
#   tests/fuzz/run.sh [SECONDS_PER_TARGET] [TARGET...]     (default 240 s, every target)
# Targets: oculus mission frame_png ply nav_import params_yaml noise_model mesh session aris mcap db3. The working corpus grows in
# build/fuzz/corpus/<target> (the seeds in tests/fuzz/corpus/<target> are read, not written);
# crash, leak, timeout and out-of-memory inputs land in build/fuzz/artifacts/<target>/. Copy
# each one into tests/fuzz/corpus/<target>/ once fixed: the unit test FuzzRegression replays it.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-240}"
shift || true
declare -A binary=([oculus]=fuzz_oculusLog [mission]=fuzz_mission [frame_png]=fuzz_framePng
                   [ply]=fuzz_plyPointCloud [nav_import]=fuzz_navImport
                   [params_yaml]=fuzz_paramsYaml [noise_model]=fuzz_noiseModel
                   [mesh]=fuzz_referenceMesh [session]=fuzz_sessionFile
                   [aris]=fuzz_arisFile [mcap]=fuzz_mcapBag [db3]=fuzz_sqliteBag)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(oculus mission frame_png ply nav_import params_yaml noise_model mesh session aris mcap db3)
status=0
for t in "${targets[@]}"; do
  exe="build/fuzz/tests/fuzz/${binary[$t]}"
  [ -x "$exe" ] || { echo "missing $exe: cmake --preset fuzz && cmake --build --preset fuzz" >&2; exit 2; }
  mkdir -p "build/fuzz/corpus/$t" "build/fuzz/artifacts/$t"
  log="build/fuzz/artifacts/$t/fuzz.log"
  scratch="build/fuzz/scratch/$t-$$"
  echo "== $t: $seconds s"
  if SONARCARVE_FUZZ_SCRATCH="$scratch" "$exe" "build/fuzz/corpus/$t" "tests/fuzz/corpus/$t" -max_total_time="$seconds" \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="build/fuzz/artifacts/$t/" >"$log" 2>&1; then
    grep -E "^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)|^Done" "$log" || true
  else
    status=1
    grep -E "ERROR|SUMMARY|Test unit written" "$log" || true
  fi
  rm -rf "$scratch"
done
exit $status
