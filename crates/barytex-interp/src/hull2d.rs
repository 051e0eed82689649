//! 2D convex hull with exact orientation.
