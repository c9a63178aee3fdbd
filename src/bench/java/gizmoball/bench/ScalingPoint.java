package gizmoball.bench;

/** Cost per tick of a random board of this size, with or without the spatial index. */
record ScalingPoint(String axis, int gizmos, int balls, boolean spatialIndex, double usPerTick) {}
