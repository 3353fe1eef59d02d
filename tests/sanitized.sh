#!/usr/bin/env bash
# The whole test suite again under AddressSanitizer and UndefinedBehaviorSanitizer, in a
# second build directory (docs/reliability.md); any finding fails the run. Leaks that
# third-party libraries keep for the process's life are suppressed by library name
# (tests/sanitizers/lsan.supp).
set -euo pipefail
cd "$(dirname "$0")/.."
# The benchmarks are not built: no test runs them, and their figures are the plain build's.
cmake -S . -B build-san -DMMVLAB_SANITIZE=ON -DMMVLAB_SANITIZED_READER_TEST=OFF -DMMVLAB_BUILD_BENCH=OFF >/dev/null
cmake --build build-san -j"$(nproc)"
# intercept_tls_get_addr=0: Debian 12's sanitizer runtime (GCC 12) takes a dynamic TLS
# block whose address is 16 past a page boundary for a pre-2.25 glibc block with a header
# and reads its start and size from the two words before it; since glibc 2.25 those words
# are whatever malloc left there, and LeakSanitizer's stop-the-world tracer then scans a
# range that is not mapped and dies ("Tracer caught signal 11 ... LeakSanitizer has
# encountered a fatal error") after the test body has passed. It hit CI once in a
# place-sensors run that had drawn with Mesa (dlopen'd, dynamic TLS). LLVM replaced the
# heuristic in 2023 (after GCC 13's runtime); see docs/reliability.md.
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Left to the plain suite: tests that run at length code the sanitized suite runs in
# shorter tests, which took 580 of its 1900 CPU-seconds (CI has 45 minutes on 2 cores):
#   cluster.*                   the sweep through slurmctld and srun (SweepRunner.*, Cli.Sweep*)
#   install.*                   the same binaries copied to a prefix (the plain suite installs them)
#   Progress.EveryVerbNames...  every verb made to run long (each verb runs in Cli.*)
#   Signals.*, Cli.*Killed*     kills at timed moments (the handlers run in
#                               Cli.RenderLeavesNoTemporaryBehind, OutputDirTest.ASignal*)
#   Cli.FrfTargetErrorBounds... the frf ladder to 64 segments (Consistency.FrfMeshErrorEstimate*)
#   Cli.TargetErrorMeetsItsTargetOnTheSpatialArticle   (TargetError.*, Cli.FrfOnTheSpatialArticle*)
#   Update.NoisyFrequencies...  20 noisy repeats of an update (Update.*, Cli.Update*)
#   Extremes.LongFreeRunEnergyDrift   a long free run (Extremes.*, Simulation.*)
#   SegmentsForTarget.TheDefaultArticleMeetsAFineReference   a fine-mesh reference (Converge.*)
#   readback.report_page_in_a_browser   Chromium loading and printing two report pages
#                               (the reports themselves: Cli.Report*)
#   Fidelity.TheDefaultRunMeetsItsStatedAccuracy...   a segment-model reference run
#                               (the modal default and its verification:
#                               TargetError.TheScenesOwnModalRunIsVerifiedAgainstTwiceItsModes)
#   Cli.EveryShippedScenesDefaultRun...   every shipped scene's whole default run and its
#                               companion (9 s plain, HAM-SAS's RK-Merson at 1e-8 most of it;
#                               --verify and its companions: Verify.*, Cli.SimulateVerify*)
#   figures.layout_of_every_shipped_figure, golden.figures_reproduced, readback.csv_*,
#   readback.vtk_*              every verb's files judged by their content (layout, bytes,
#                               Python's, Octave's and VTK's readers): the same numbers under
#                               the sanitizers; the verbs and their figures run under them in
#                               Cli.*, Consistency.* and Faults.* (309 of the suite's 2911
#                               CPU-seconds with these, 2026-11-29)
LONG='^cluster\.|^install\.|^Progress\.EveryVerbNamesItsStageWhenItRunsLong$|^Signals\.|^Cli\.KilledRunsLeaveNoPartialFile$'
LONG+='|^Cli\.SweepKilledAtRandomMomentsResumesToTheSameFile$|^Cli\.FrfTargetErrorBoundsTheFrf$'
LONG+='|^Cli\.TargetErrorMeetsItsTargetOnTheSpatialArticle$|^Update\.NoisyFrequenciesLeaveTheTruthInsideTheIntervals$'
LONG+='|^Extremes\.LongFreeRunEnergyDrift$|^SegmentsForTarget\.TheDefaultArticleMeetsAFineReference$'
LONG+='|^readback\.report_page_in_a_browser$|^Fidelity\.TheDefaultRunMeetsItsStatedAccuracyAndVerifySeesTheModesLeftOut$'
LONG+='|^figures\.layout_of_every_shipped_figure$|^golden\.figures_reproduced$|^readback\.csv_files_read_as_written$'
LONG+='|^readback\.vtk_files_read_by_vtk$|^Cli\.EveryShippedScenesDefaultRunStatesItsFidelityAndMeetsItsAccuracy$'
ctest --test-dir build-san --output-on-failure -j"$(nproc)" --timeout 900 -E "$LONG"

