/** Stability tests: long runs of hard cases (corners, seams, piles, pinches, fast balls) with invariants every tick. */
package gizmoball.stability;
