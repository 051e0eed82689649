//! Exact 3D orientation (the sign of a 4×4 determinant).
