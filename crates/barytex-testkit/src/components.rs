//! Flatten interpolable values into `f64` components, for comparisons in generic tests.

use glam::{DVec2, DVec3, DVec4, Vec2, Vec3, Vec3A, Vec4};

/// A value whose components can be listed as `f64`s (exactly: f32 widens losslessly).
pub trait Components {
    /// Append the components to `out`.
    fn push_components(&self, out: &mut Vec<f64>);

    /// The components as a vector.
    fn components(&self) -> Vec<f64> {
        let mut out = Vec::new();
        self.push_components(&mut out);
        out
    }
}

impl Components for f32 {
    fn push_components(&self, out: &mut Vec<f64>) {
        out.push(f64::from(*self));
    }
}

impl Components for f64 {
    fn push_components(&self, out: &mut Vec<f64>) {
        out.push(*self);
    }
}

macro_rules! impl_vec {
    ($($t:ty),+) => {$(
        impl Components for $t {
            fn push_components(&self, out: &mut Vec<f64>) {
                out.extend(self.to_array().iter().map(|&c| c as f64));
            }
        }
    )+};
}

impl_vec!(Vec2, Vec3, Vec3A, Vec4, DVec2, DVec3, DVec4);

impl<T: Components, const N: usize> Components for [T; N] {
    fn push_components(&self, out: &mut Vec<f64>) {
        for v in self {
            v.push_components(out);
        }
    }
}

macro_rules! impl_tuple {
    ($($name:ident $idx:tt),+) => {
        impl<$($name: Components),+> Components for ($($name,)+) {
            fn push_components(&self, out: &mut Vec<f64>) {
                $(self.$idx.push_components(out);)+
            }
        }
    };
}

impl_tuple!(A 0);
impl_tuple!(A 0, B 1);
impl_tuple!(A 0, B 1, C 2);
impl_tuple!(A 0, B 1, C 2, D 3);
