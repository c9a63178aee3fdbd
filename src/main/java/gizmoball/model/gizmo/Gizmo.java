package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;

/**
 * A gizmo on the board as views, controllers and the editor see it, read only (each kind adds its own read-only
 * view). Coordinates are whole cells; the footprint is the rectangle x..x+width, y..y+height.
 */
public sealed interface Gizmo permits BumperView, FlipperView, AbsorberView, SinkView, AcceleratorView, SpawnerView, GateView,
        DropTargetView, PortalView, SpinnerView {
    String name();

    GizmoKind kind();

    int x();

    int y();

    int width();

    int height();

    /** Quarter turns clockwise, 0..3; always 0 for CIRCLE and ABSORBER. */
    int rotation();

    /** 1.0 for bumpers, 0.95 for flippers, 0 for the absorber (it captures instead of reflecting). */
    double reflectionCoefficient();

    /** Board time of the last trigger or hit, NEGATIVE_INFINITY if never. */
    double lastTriggeredAt();

    /** Its own colour, or empty for the kind's colour (see {@link Rgb}). */
    Optional<Rgb> colour();

    /** The value its author set on it beyond its place, turn and colour; {@link Setting.None} for most kinds. */
    Setting setting();

    /**
     * The names of the balls it holds, longest-held first: an absorber's ({@link GizmoKind#ballTaking} {@code HOLDS});
     * none for every other kind.
     */
    List<String> held();

    /**
     * How it launches when it is a plunger (an absorber whose {@link Setting.Pull} has one); empty for an absorber that
     * fires at once and for every other kind.
     */
    Optional<Plunger> plunger();

    /** How far it is pulled as a plunger, 0 (at rest, or no plunger) to 1 (a full pull). */
    double pull();

    /** The quarter turn its key swings its bar through (a flipper's); empty for every other kind. */
    Optional<Sweep> sweep();

    /** What play has changed of it, for a save during play; {@link PlayState.AsBuilt} for most kinds and at rest. */
    PlayState playState();
}
