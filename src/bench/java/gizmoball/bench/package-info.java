/** The benchmark ({@code gradle bench}): speed against accuracy, scaling, soak, preview, steady state, fuzz. */
package gizmoball.bench;
