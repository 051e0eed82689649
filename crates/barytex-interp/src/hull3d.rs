//! 3D convex hull with exact orientation.
