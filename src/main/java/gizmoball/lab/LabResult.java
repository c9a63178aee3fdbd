package gizmoball.lab;

/** A lab run: its report, and where the balls went in the autoplayer's games. */
public record LabResult(LabReport report, HeatGrid autoplayerHeat) {
}
