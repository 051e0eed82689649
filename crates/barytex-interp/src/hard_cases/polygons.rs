//! Hard cases for generalized barycentric coordinates over polygons.
