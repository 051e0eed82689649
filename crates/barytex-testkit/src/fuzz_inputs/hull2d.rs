//! Byte layout and checks of the `hull2d` fuzz target.
