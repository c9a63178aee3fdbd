package gizmoball.model;

/**
 * What of a key press a key binding reacts to: {@link #DOWN} the press, {@link #UP} the release (a flipper bound
 * to them swings up while the key is held), {@link #CHANGE} the press as a trigger: the gizmo performs its action
 * as when it is hit (a flipper toggles, an absorber fires).
 */
public enum KeyEdge { DOWN, UP, CHANGE }
