/** The gizmo kinds: their footprints, shapes, solid bodies, colours and what each does when driven. */
package gizmoball.model.gizmo;
