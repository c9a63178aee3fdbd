package gizmoball.model;

/** The board's gravity and friction, checked as they are set; the defaults are {@link Board}'s. */
final class PhysicsConstants {
    private double gravity = Board.DEFAULT_GRAVITY;
    private double mu = Board.DEFAULT_MU;
    private double mu2 = Board.DEFAULT_MU2;

    double gravity() {
        return gravity;
    }

    double mu() {
        return mu;
    }

    double mu2() {
        return mu2;
    }

    void setGravity(double g) {
        if (!Double.isFinite(g)) {
            throw new BoardEditException("gravity must be a finite number, got " + g);
        }
        gravity = g;
    }

    void setFriction(double newMu, double newMu2) {
        if (!Double.isFinite(newMu) || !Double.isFinite(newMu2) || newMu < 0 || newMu2 < 0) {
            throw new BoardEditException("friction must be finite and not negative, got mu " + newMu + ", mu2 " + newMu2);
        }
        mu = newMu;
        mu2 = newMu2;
    }

    void reset() {
        gravity = Board.DEFAULT_GRAVITY;
        mu = Board.DEFAULT_MU;
        mu2 = Board.DEFAULT_MU2;
    }

    void copyFrom(PhysicsConstants source) {
        gravity = source.gravity;
        mu = source.mu;
        mu2 = source.mu2;
    }
}
