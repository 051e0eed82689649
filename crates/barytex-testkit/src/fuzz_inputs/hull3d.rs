//! Byte layout and checks of the `hull3d` fuzz target.
