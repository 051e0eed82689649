//! Float functions that `core` lacks, from `std` when present, else from `libm`.

#[cfg(feature = "std")]
#[inline]
pub(crate) fn sqrt(x: f64) -> f64 {
    x.sqrt()
}

#[cfg(all(not(feature = "std"), feature = "libm"))]
#[inline]
pub(crate) fn sqrt(x: f64) -> f64 {
    libm::sqrt(x)
}

#[cfg(feature = "std")]
#[inline]
pub(crate) fn fma_f32(a: f32, b: f32, c: f32) -> f32 {
    a.mul_add(b, c)
}

#[cfg(all(not(feature = "std"), feature = "libm"))]
#[inline]
pub(crate) fn fma_f32(a: f32, b: f32, c: f32) -> f32 {
    libm::fmaf(a, b, c)
}

macro_rules! float_fns {
    ($($name:ident($($arg:ident: $t:ty),*) -> $r:ty = $std:expr, $libm:path;)*) => {$(
        #[cfg(feature = "std")]
        #[inline]
        pub(crate) fn $name($($arg: $t),*) -> $r {
            $std
        }

        #[cfg(all(not(feature = "std"), feature = "libm"))]
        #[inline]
        pub(crate) fn $name($($arg: $t),*) -> $r {
            $libm($($arg),*)
        }
    )*};
}

float_fns! {
    sqrt_f32(x: f32) -> f32 = x.sqrt(), libm::sqrtf;
    sin_cos(x: f64) -> (f64, f64) = x.sin_cos(), libm::sincos;
    atan2(y: f64, x: f64) -> f64 = y.atan2(x), libm::atan2;
}
