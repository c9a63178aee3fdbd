package gizmoball.session;

/** What the window is doing with its board: playing it, or editing it. */
public enum Mode { PLAY, BUILD }
