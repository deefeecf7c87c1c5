// The loop budget (common.h, SPEC_LOOP_BUDGET): lavapipe counts the passes of every loop of a
// kernel per SIMD group, one budget for all, and silently drops the rest of the work after
// 65 535. A SIMD group is a subgroup there (8 lanes), and the lanes in a loop make its passes
// together: the group makes as many passes as its busiest lane, plus the one lavapipe may make
// with every lane masked off to test a condition at the top. So each loop whose passes grow
// with the scene (over Frame's counts, the sphere tree's walks) counts its passes per lane and,
// where its lanes meet again after it, one of them adds the group's count to its tally; the
// group's tallies add up to its passes, checked at the end of main. (A lane that leaves such a
// loop by `return` would skip the count: they break.) The other loops are bounded by constants
// per sample, LOOP_PASSES_PER_SAMPLE at most, and reserved for. Kernels without a counted loop,
// or without a budget (other devices), compile all of this to nothing.

// Whether the kernel has a budget and a loop that grows with the scene. (No || or &&: glslang
// turns them into branches, invalid SPIR-V outside a function.)
const bool COUNTED_LOOPS = (uint(LOOP_BUDGET > 0u) &
                            (uint(SPHERE_TREE != SPHERE_TREE_NONE) | uint(SPHERE_COUNT == COUNT_FROM_FRAME) |
                             uint(PLANE_COUNT == COUNT_FROM_FRAME) | uint(LIGHT_COUNT == COUNT_FROM_FRAME))) != 0u;

uint loopTally = 0u;  // passes this lane counted for its group

// After a counted loop in which this lane made `passes` passes.
void countLoop(uint passes) {
  if (!COUNTED_LOOPS) return;
  uint groupPasses = subgroupMax(passes) + 1u;
  if (subgroupElect()) loopTally += groupPasses;
}

// At the end of main, with every lane of the group: reports a group over the budget, with the
// reserve for `samples` samples (and a pass of the loop over them each).
void checkLoopBudget(uint samples) {
  if (!COUNTED_LOOPS) return;
  if (subgroupAdd(loopTally) + samples * (LOOP_PASSES_PER_SAMPLE + 1u) > LOOP_BUDGET && subgroupElect())
    atomicOr(status[0], STATUS_LOOP_BUDGET);
}
