package gizmoball.model;

/** Which edge of a key press a key binding reacts to. */
public enum KeyEdge { DOWN, UP }
