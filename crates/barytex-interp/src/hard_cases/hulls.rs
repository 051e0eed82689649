//! Hard cases for the 2D and 3D convex hulls.
