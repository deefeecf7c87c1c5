#!/usr/bin/env bash
# The test suite built with ASan and UBSan, on lavapipe. Any sanitizer report fails the test
# that caused it. CI runs this after the README's test command. Left out: the fuzz label (its
# own ASan build), and the sweeps that render many scenes or kinds through kernel variants and
# compare images (SWEEPS below), and the command-line test `cli`. The sweeps' host path (packing,
# upload, pipelines, readback) is the one every other render test runs here; what they add is
# shader coverage, which the README's test command runs in full. `cli` starts raytex a few
# hundred times to check exit codes and messages; the code it reaches (parsing, errors, output
# files, renders) runs here through the unit, render, malformed and output tests. The benchmarks
# are not built. The unit tests run as four processes, not one each (tests/CMakeLists.txt).
# Timings: docs/architecture.md, "Functions and tests".
# Usage: tests/sanitize/run.sh [BUILD_DIR]   (default build-sanitize)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build-sanitize}
# -O1 -g1 (line tables for the reports' stacks): the tests' time is the driver's, which is not
# instrumented, and -O2 -g took twice as long to compile. The test executables' own files at
# -O0: when this was chosen, the build took 227 s instead of 328 s on two cores.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DRAYTEX_SANITIZE=ON -DRAYTEX_BENCH=OFF \
  -DRAYTEX_TEST_OPTIMIZE=-O0 >/dev/null
cmake --build "$build"
supp=$PWD/tests/sanitize
# detect_leaks: on, with the driver's and loader's own allocations suppressed (lsan.supp says
# which and why). abort_on_error: a report is a failing exit, even where a caller ignores codes.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export RAYTEX_SANITIZED=1  # tests/app/cli_test.sh, output_test.sh: skip the address-space limit tests (ASan's shadow needs terabytes)
SWEEPS='BakedKernelsMatchTheUniformBuffers|(CourseScenes|Fields)RenderWhatTheOneKernelRenders|NoiseFilterTest|Shadow(Lists|Grids)RenderWhatTheTreeWalkRenders|RendersWhatTheLoopOverEverySphereRenders'
# Image comparisons of kernel variants and filters, bit for bit or against a reference (the same
# host path as the rest: passes, the coverage filter's dispatches and supersampling run here in
# AovTest, CoverageTest.RendersAtTheLoopLimit and ProgressiveEqualsLoop):
SWEEPS+='|ImageFilterTest|OctaveClampingTest|BoxFilterBeatsPointSampling|HorizonBandBoxBeatsPointSampling|FullBlocksRenderTheirLastItems|CourseMaterialsMatchTheUnspecialisedKernel|AllScenesFiniteWhenSupersampledAndFiltered|FilteredCheckerBeatsSupersamplingAtTheHorizon|IdentityPlacementIsExact|TileKernelsWriteThePassesOfTheOneKernel'
SWEEPS+='|EachEdgeAloneMatchesTheReferencePixelByPixel|CourseSceneIsCloserToTheReferenceThanTheBoxFilter'
SWEEPS+='|ShadedImageIsBitIdenticalWithPasses|SupersampledPassesComeFromThePixelCentre|PixelsNoEdgeCrossesAreBitIdenticalToTheBoxFilter'
SWEEPS+='|FilteredNoiseKinds(AreFiniteOnSpheresAndGrazingPlanes|TendToPointSamplingUnderMagnification)'
SWEEPS+='|RotatedScaledCheckerBoxFilterMatchesSupersampledReference|SupersamplingConvergesToTheReference'
ctest --test-dir "$build" -LE fuzz -E "^cli\$|$SWEEPS" --output-on-failure -j3
