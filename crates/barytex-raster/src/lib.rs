//! A reference software rasterizer: exact where GPUs are exact (fixed-point edge functions, the
//! top-left fill rule), correct where the peers are not (near-plane clipping, derivatives),
//! deterministic for any thread count.
#![forbid(unsafe_code)]
