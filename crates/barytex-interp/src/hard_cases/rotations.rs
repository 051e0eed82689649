//! Hard cases for the SLERP family: nearly equal and nearly antipodal rotations, (nearly) antiparallel vectors.
