package gizmoball.model.gizmo;

/** What views, controllers and the editor see of a sink: its cell, read only (it holds nothing it shows). */
public sealed interface SinkView extends Gizmo permits Sink {
}
