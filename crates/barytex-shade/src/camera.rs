//! A pinhole camera with matrices written out by hand: a right-handed look-at view (the eye looks
//! down its −z) and a Vulkan/wgpu perspective projection (clip z in `[0, w]`, y up), the
//! conventions of `barytex-raster`.

use glam::{Mat4, Vec3, Vec4};

/// The view matrix of an eye at `eye` looking at `target` with `up` roughly up; `None` when
/// the eye and target coincide, `up` is parallel to the view direction, or anything is not
/// finite.
///
/// ```
/// use barytex_shade::camera::look_at;
/// use glam::Vec3;
///
/// let view = look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).expect("regular");
/// // The target lies 5 units down the eye's −z.
/// assert_eq!(view.transform_point3(Vec3::ZERO), Vec3::new(0.0, 0.0, -5.0));
/// ```
#[must_use]
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Option<Mat4> {
    if !(eye.is_finite() && target.is_finite() && up.is_finite()) {
        return None;
    }
    let forward = (target - eye).try_normalize()?;
    let right = forward.cross(up).try_normalize()?;
    let true_up = right.cross(forward);
    Some(Mat4::from_cols(
        Vec4::new(right.x, true_up.x, -forward.x, 0.0),
        Vec4::new(right.y, true_up.y, -forward.y, 0.0),
        Vec4::new(right.z, true_up.z, -forward.z, 0.0),
        Vec4::new(-right.dot(eye), -true_up.dot(eye), forward.dot(eye), 1.0),
    ))
}

/// Perspective projection with vertical field of view `fov_y` (radians), `aspect = width /
/// height`, depth mapped to clip z ∈ `[0, w]` between `near` and `far` (Vulkan/wgpu).
///
/// No checks: a zero `aspect`, `fov_y` or `near = far` gives infinite or NaN entries, which the
/// rasterizer drops (it counts non-finite triangles).
#[must_use]
pub fn perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let f = 1.0 / (fov_y / 2.0).tan();
    Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, far / (near - far), -1.0),
        Vec4::new(0.0, 0.0, near * far / (near - far), 0.0),
    )
}

/// Where the eye is and how the world reaches clip space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The eye position in world space.
    pub eye: Vec3,
    /// World → view.
    pub view: Mat4,
    /// View → clip.
    pub projection: Mat4,
}

impl Camera {
    /// A camera at `eye` looking at `target` (`up` roughly up); see [`look_at`] and
    /// [`perspective`]. `None` where [`look_at`] is.
    ///
    /// ```
    /// use barytex_shade::Camera;
    /// use glam::Vec3;
    ///
    /// let cam = Camera::look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y,
    ///     60f32.to_radians(), 1.0, 0.1, 10.0).expect("regular");
    /// let clip = cam.view_projection() * Vec3::ZERO.extend(1.0);
    /// assert!(clip.x.abs() < 1e-6 && clip.y.abs() < 1e-6 && clip.z > 0.0 && clip.z < clip.w);
    /// ```
    #[must_use]
    #[allow(clippy::too_many_arguments)]
    pub fn look_at(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        fov_y: f32,
        aspect: f32,
        near: f32,
        far: f32,
    ) -> Option<Self> {
        Some(Self {
            eye,
            view: look_at(eye, target, up)?,
            projection: perspective(fov_y, aspect, near, far),
        })
    }

    /// World → clip.
    #[must_use]
    pub fn view_projection(&self) -> Mat4 {
        self.projection * self.view
    }

    /// The unit direction the eye looks along, in world space.
    #[must_use]
    pub fn forward(&self) -> Vec3 {
        -Vec3::new(self.view.x_axis.z, self.view.y_axis.z, self.view.z_axis.z)
    }
}
