//! Byte layout and checks of the `slerp` fuzz target.
