//! Generalized barycentric coordinates over convex polygons (Wachspress, mean value).
