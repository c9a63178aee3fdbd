package gizmoball.model.gizmo;

import physics.Vect;

/** What views, controllers and the editor see of a spawner: where its balls appear and how fast, read only. */
public sealed interface SpawnerView extends Gizmo permits Spawner {
    /** The velocity a spawned ball starts with. */
    Vect velocity();

    /** Where the centre of a spawned ball of that radius starts: touching the side it faces, mid-side. */
    Vect mouth(double ballRadius);
}
