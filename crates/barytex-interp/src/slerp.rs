//! The SLERP family: exact quaternion and unit-vector slerp, and fast approximations.
