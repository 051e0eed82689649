//! Byte layout and checks of the `polygon` fuzz target.
