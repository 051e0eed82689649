//! Accessors, read by this crate rather than by the `gltf` crate: every range is checked against
//! its bufferView and buffer when the document is parsed (offset + stride·(count−1) + element
//! size), so reading can never run off a slice, and sparse substitution is validated (indices
//! strictly increasing and in range) before it is applied.

use std::collections::BTreeSet;

use crate::json::{Obj, as_obj};
use crate::{SceneError, SceneLimits};

/// A component type (`componentType`, a GL enum).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ComponentType {
    /// `BYTE` (5120).
    I8,
    /// `UNSIGNED_BYTE` (5121).
    U8,
    /// `SHORT` (5122).
    I16,
    /// `UNSIGNED_SHORT` (5123).
    U16,
    /// `UNSIGNED_INT` (5125).
    U32,
    /// `FLOAT` (5126).
    F32,
}

impl ComponentType {
    pub(crate) fn from_gl(v: u64) -> Option<Self> {
        Some(match v {
            5120 => Self::I8,
            5121 => Self::U8,
            5122 => Self::I16,
            5123 => Self::U16,
            5125 => Self::U32,
            5126 => Self::F32,
            _ => return None,
        })
    }

    pub(crate) fn size(self) -> u64 {
        match self {
            Self::I8 | Self::U8 => 1,
            Self::I16 | Self::U16 => 2,
            Self::U32 | Self::F32 => 4,
        }
    }

    /// Reads one component at the start of `b` (which holds at least `size()` bytes) as f32,
    /// applying the glTF normalisation formulas when `normalized`
    /// (`max(c / 127, −1)`, `c / 255`, `max(c / 32767, −1)`, `c / 65535`).
    pub(crate) fn read_f32(self, b: &[u8], normalized: bool) -> f32 {
        let byte = |i: usize| b.get(i).copied().unwrap_or(0);
        match self {
            Self::I8 => {
                let v = f32::from(i8::from_le_bytes([byte(0)]));
                if normalized { (v / 127.0).max(-1.0) } else { v }
            }
            Self::U8 => {
                let v = f32::from(byte(0));
                if normalized { v / 255.0 } else { v }
            }
            Self::I16 => {
                let v = f32::from(i16::from_le_bytes([byte(0), byte(1)]));
                if normalized {
                    (v / 32767.0).max(-1.0)
                } else {
                    v
                }
            }
            Self::U16 => {
                let v = f32::from(u16::from_le_bytes([byte(0), byte(1)]));
                if normalized { v / 65535.0 } else { v }
            }
            Self::U32 => {
                #[allow(clippy::cast_precision_loss)]
                let v = u32::from_le_bytes([byte(0), byte(1), byte(2), byte(3)]) as f32;
                v
            }
            Self::F32 => f32::from_le_bytes([byte(0), byte(1), byte(2), byte(3)]),
        }
    }

    /// Reads one unsigned integer component (indices); `None` for signed and float types.
    pub(crate) fn read_u32(self, b: &[u8]) -> Option<u32> {
        let byte = |i: usize| b.get(i).copied().unwrap_or(0);
        match self {
            Self::U8 => Some(u32::from(byte(0))),
            Self::U16 => Some(u32::from(u16::from_le_bytes([byte(0), byte(1)]))),
            Self::U32 => Some(u32::from_le_bytes([byte(0), byte(1), byte(2), byte(3)])),
            _ => None,
        }
    }
}

/// An element type (`type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ElementType {
    Scalar,
    Vec2,
    Vec3,
    Vec4,
    Mat2,
    Mat3,
    Mat4,
}

impl ElementType {
    fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "SCALAR" => Self::Scalar,
            "VEC2" => Self::Vec2,
            "VEC3" => Self::Vec3,
            "VEC4" => Self::Vec4,
            "MAT2" => Self::Mat2,
            "MAT3" => Self::Mat3,
            "MAT4" => Self::Mat4,
            _ => return None,
        })
    }

    /// (columns, rows).
    fn shape(self) -> (u64, u64) {
        match self {
            Self::Scalar => (1, 1),
            Self::Vec2 => (1, 2),
            Self::Vec3 => (1, 3),
            Self::Vec4 => (1, 4),
            Self::Mat2 => (2, 2),
            Self::Mat3 => (3, 3),
            Self::Mat4 => (4, 4),
        }
    }

    pub(crate) fn components(self) -> usize {
        let (c, r) = self.shape();
        usize::try_from(c * r).unwrap_or(16)
    }

    pub(crate) fn is_matrix(self) -> bool {
        matches!(self, Self::Mat2 | Self::Mat3 | Self::Mat4)
    }
}

/// The byte layout of one element: matrix columns start on 4-byte boundaries (glTF 2.0 §3.6.2.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Layout {
    pub(crate) component: ComponentType,
    pub(crate) element: ElementType,
}

impl Layout {
    fn column_stride(self) -> u64 {
        let (_, rows) = self.element.shape();
        let raw = rows * self.component.size();
        if self.element.is_matrix() {
            raw.div_ceil(4) * 4
        } else {
            raw
        }
    }

    /// Bytes one element occupies, padding included: the distance between tightly packed
    /// elements.
    pub(crate) fn element_size(self) -> u64 {
        let (cols, _) = self.element.shape();
        cols * self.column_stride()
    }

    /// Bytes an element's data reaches: [`element_size`](Self::element_size) without the last
    /// column's trailing padding. The padding only separates a column from what follows it
    /// (glTF 2.0 §3.6.2.4), so the last element of a bufferView may end here; the
    /// glTF-Validator's element length is the same (6 for MAT2 of 1-byte components, 11 and 22
    /// for MAT3 of 1- and 2-byte ones).
    pub(crate) fn element_bytes(self) -> u64 {
        let (cols, rows) = self.element.shape();
        (cols - 1) * self.column_stride() + rows * self.component.size()
    }

    /// Byte offset of component `j` (column-major) inside an element.
    fn component_offset(self, j: u64) -> u64 {
        let (_, rows) = self.element.shape();
        (j / rows) * self.column_stride() + (j % rows) * self.component.size()
    }
}

/// A bufferView, validated against its buffer.
#[derive(Clone, Debug)]
pub(crate) struct ViewDef {
    pub(crate) buffer: usize,
    pub(crate) offset: u64,
    pub(crate) length: u64,
    pub(crate) stride: Option<u64>,
    /// `target`: 34962 `ARRAY_BUFFER`, 34963 `ELEMENT_ARRAY_BUFFER`.
    pub(crate) target: Option<u64>,
}

impl ViewDef {
    pub(crate) fn parse(obj: Obj<'_>, buffer_lengths: &[u64]) -> Result<Self, SceneError> {
        let buffer = obj.req_index("buffer", buffer_lengths.len(), "buffer")?;
        let offset = obj.opt_u64("byteOffset")?.unwrap_or(0);
        let length = obj.req_u64("byteLength")?;
        if length == 0 {
            return Err(obj.error("byteLength", "byteLength must be ≥ 1"));
        }
        let buffer_length = buffer_lengths.get(buffer).copied().unwrap_or(0);
        if offset
            .checked_add(length)
            .is_none_or(|end| end > buffer_length)
        {
            return Err(SceneError::invalid(
                obj.ptr,
                format!(
                    "byteOffset {offset} + byteLength {length} exceeds buffer {buffer}'s byteLength {buffer_length}"
                ),
            ));
        }
        let stride = obj.opt_u64("byteStride")?;
        if let Some(s) = stride {
            if !(4..=252).contains(&s) {
                return Err(obj.error("byteStride", format!("byteStride {s} outside [4, 252]")));
            }
            if s % 4 != 0 {
                return Err(obj.error(
                    "byteStride",
                    format!("byteStride {s} is not a multiple of 4"),
                ));
            }
            if s > length {
                return Err(obj.error(
                    "byteStride",
                    format!("byteStride {s} exceeds byteLength {length}"),
                ));
            }
        }
        let target = obj.opt_u64("target")?;
        if target == Some(34963) && stride.is_some() {
            return Err(obj.error(
                "byteStride",
                "an ELEMENT_ARRAY_BUFFER view must not define byteStride",
            ));
        }
        Ok(Self {
            buffer,
            offset,
            length,
            stride,
            target,
        })
    }
}

/// A sparse substitution (`accessor.sparse`).
#[derive(Clone, Debug)]
pub(crate) struct SparseDef {
    pub(crate) count: u64,
    pub(crate) indices_view: usize,
    pub(crate) indices_offset: u64,
    pub(crate) indices_component: ComponentType,
    pub(crate) values_view: usize,
    pub(crate) values_offset: u64,
}

/// An accessor, validated against its views.
#[derive(Clone, Debug)]
pub(crate) struct AccessorDef {
    pub(crate) ptr: String,
    pub(crate) view: Option<usize>,
    pub(crate) offset: u64,
    pub(crate) count: u64,
    /// `None` when the type or component type is unknown (an error only if the accessor is used).
    pub(crate) layout: Option<Layout>,
    pub(crate) normalized: bool,
    pub(crate) sparse: Option<SparseDef>,
    pub(crate) has_bounds: bool,
    /// Declared `min`/`max` (raw, un-normalised values), when present and well-formed.
    pub(crate) min: Option<Vec<f64>>,
    pub(crate) max: Option<Vec<f64>>,
}

fn check_range(
    ptr: &str,
    what: &str,
    view: &ViewDef,
    offset: u64,
    stride: u64,
    count: u64,
    element_size: u64,
) -> Result<(), SceneError> {
    let end = count
        .checked_sub(1)
        .and_then(|n| n.checked_mul(stride))
        .and_then(|n| n.checked_add(offset))
        .and_then(|n| n.checked_add(element_size));
    match end {
        Some(end) if end <= view.length => Ok(()),
        _ => Err(SceneError::invalid(
            ptr,
            format!(
                "{what}: offset {offset} + stride {stride} × ({count} − 1) + element size {element_size} exceeds the bufferView's byteLength {}",
                view.length
            ),
        )),
    }
}

impl AccessorDef {
    pub(crate) fn parse(
        obj: Obj<'_>,
        views: &[ViewDef],
        limits: &SceneLimits,
        warnings: &mut Vec<String>,
    ) -> Result<Self, SceneError> {
        let count = obj.req_u64("count")?;
        if count == 0 {
            return Err(obj.error("count", "count must be ≥ 1"));
        }
        if count > limits.max_accessor_elements {
            return Err(SceneError::TooLarge {
                pointer: obj.at("count"),
                what: "accessor elements",
                requested: count,
                limit: limits.max_accessor_elements,
            });
        }
        let component_gl = obj.req_u64("componentType")?;
        let type_str = obj.req_str("type")?;
        let component = ComponentType::from_gl(component_gl);
        let element = ElementType::parse(type_str);
        if component.is_none() {
            warnings.push(format!(
                "{}: unknown componentType {component_gl}",
                obj.at("componentType")
            ));
        }
        if element.is_none() {
            warnings.push(format!("{}: unknown type {type_str:?}", obj.at("type")));
        }
        let layout = component
            .zip(element)
            .map(|(component, element)| Layout { component, element });
        let normalized = obj.opt_bool("normalized")?.unwrap_or(false);
        if normalized && matches!(component, Some(ComponentType::F32 | ComponentType::U32)) {
            return Err(obj.error(
                "normalized",
                "only BYTE, UNSIGNED_BYTE, SHORT and UNSIGNED_SHORT accessors may be normalized",
            ));
        }
        let view = obj.opt_index("bufferView", views.len(), "bufferView")?;
        if view.is_none() && count > limits.max_unbacked_accessor_elements {
            return Err(SceneError::TooLarge {
                pointer: obj.at("count"),
                what: "elements in an accessor without bufferView",
                requested: count,
                limit: limits.max_unbacked_accessor_elements,
            });
        }
        let offset = obj.opt_u64("byteOffset")?;
        if view.is_none() && offset.is_some() {
            return Err(obj.error("byteOffset", "byteOffset requires bufferView"));
        }
        let offset = offset.unwrap_or(0);
        let mut bounds: [Option<Vec<f64>>; 2] = [None, None];
        for (slot, key) in bounds.iter_mut().zip(["min", "max"]) {
            if let Some(arr) = obj.opt_array(key)? {
                if let Some(e) = element
                    && arr.len() != e.components()
                {
                    return Err(obj.error(
                        key,
                        format!(
                            "{} values for a {}-component type",
                            arr.len(),
                            e.components()
                        ),
                    ));
                }
                let mut values = Vec::with_capacity(arr.len());
                for (i, v) in arr.iter().enumerate() {
                    let p = crate::json::child(&obj.at(key), &i.to_string());
                    crate::json::as_f32(v, &p)?;
                    values.push(v.as_f64().unwrap_or(0.0));
                }
                *slot = Some(values);
            }
        }
        let [min, max] = bounds;
        let has_bounds = obj.get("min").is_some() && obj.get("max").is_some();
        if let (Some(layout), Some(vi)) = (layout, view) {
            let v = views
                .get(vi)
                .ok_or_else(|| obj.error("bufferView", "unresolved bufferView"))?;
            let size = layout.component.size();
            if offset % size != 0 {
                return Err(obj.error(
                    "byteOffset",
                    format!("byteOffset {offset} is not a multiple of the component size {size}"),
                ));
            }
            if !v.offset.wrapping_add(offset).is_multiple_of(size) {
                return Err(obj.error(
                    "byteOffset",
                    format!("bufferView offset + byteOffset is not a multiple of the component size {size}"),
                ));
            }
            let element_size = layout.element_size();
            if layout.element.is_matrix()
                && layout.component.size() < 4
                && let Some(s) = v.stride
                && s % 4 != 0
            {
                return Err(obj.error("bufferView", "matrix columns must be 4-byte aligned"));
            }
            if let Some(s) = v.stride
                && s < element_size
            {
                return Err(obj.error(
                    "bufferView",
                    format!("byteStride {s} is smaller than the element size {element_size}"),
                ));
            }
            let stride = v.stride.unwrap_or(element_size);
            let bytes = layout.element_bytes();
            check_range(obj.ptr, "accessor", v, offset, stride, count, bytes)?;
        }
        let sparse = match obj.opt_obj("sparse")? {
            None => None,
            Some(s) => {
                let sptr = obj.at("sparse");
                let s = as_obj(s, &sptr)?;
                Some(parse_sparse(s, count, layout, views)?)
            }
        };
        Ok(Self {
            ptr: obj.ptr.to_owned(),
            view,
            offset,
            count,
            layout,
            normalized,
            sparse,
            has_bounds,
            min,
            max,
        })
    }

    /// Whether the accessor stores data (a bufferView or sparse values); without either it is
    /// all zeros, which value checks (tangent signs, keyframe order) do not apply to.
    pub(crate) fn stores_data(&self) -> bool {
        self.view.is_some() || self.sparse.is_some()
    }

    /// The layout, or an error naming the accessor when its type is unknown.
    pub(crate) fn layout(&self) -> Result<Layout, SceneError> {
        self.layout.ok_or_else(|| {
            SceneError::invalid(
                &self.ptr,
                "accessor with an unknown type or componentType is used",
            )
        })
    }
}

fn parse_sparse(
    s: Obj<'_>,
    count: u64,
    layout: Option<Layout>,
    views: &[ViewDef],
) -> Result<SparseDef, SceneError> {
    let sparse_count = s.req_u64("count")?;
    if sparse_count == 0 || sparse_count > count {
        return Err(s.error(
            "count",
            format!("sparse count {sparse_count} outside [1, accessor count {count}]"),
        ));
    }
    let iptr = s.at("indices");
    let indices = as_obj(
        s.get("indices")
            .ok_or_else(|| SceneError::invalid(s.ptr, "required property 'indices' is missing"))?,
        &iptr,
    )?;
    let vptr = s.at("values");
    let values = as_obj(
        s.get("values")
            .ok_or_else(|| SceneError::invalid(s.ptr, "required property 'values' is missing"))?,
        &vptr,
    )?;
    let indices_view = indices.req_index("bufferView", views.len(), "bufferView")?;
    let indices_offset = indices.opt_u64("byteOffset")?.unwrap_or(0);
    let ic = indices.req_u64("componentType")?;
    let indices_component = match ComponentType::from_gl(ic) {
        Some(c @ (ComponentType::U8 | ComponentType::U16 | ComponentType::U32)) => c,
        _ => {
            return Err(indices.error(
                "componentType",
                format!("sparse indices must be UNSIGNED_BYTE/SHORT/INT, got {ic}"),
            ));
        }
    };
    let values_view = values.req_index("bufferView", views.len(), "bufferView")?;
    let values_offset = values.opt_u64("byteOffset")?.unwrap_or(0);
    let iv = views
        .get(indices_view)
        .ok_or_else(|| indices.error("bufferView", "unresolved bufferView"))?;
    if iv.stride.is_some() {
        return Err(indices.error(
            "bufferView",
            "sparse indices' bufferView must not define byteStride",
        ));
    }
    let isize_ = indices_component.size();
    if !iv
        .offset
        .wrapping_add(indices_offset)
        .is_multiple_of(isize_)
    {
        return Err(indices.error("byteOffset", "sparse indices are misaligned"));
    }
    check_range(
        &iptr,
        "sparse indices",
        iv,
        indices_offset,
        isize_,
        sparse_count,
        isize_,
    )?;
    let vv = views
        .get(values_view)
        .ok_or_else(|| values.error("bufferView", "unresolved bufferView"))?;
    if vv.stride.is_some() {
        return Err(values.error(
            "bufferView",
            "sparse values' bufferView must not define byteStride",
        ));
    }
    if let Some(layout) = layout {
        let es = layout.element_size();
        if !vv
            .offset
            .wrapping_add(values_offset)
            .is_multiple_of(layout.component.size())
        {
            return Err(values.error("byteOffset", "sparse values are misaligned"));
        }
        check_range(
            &vptr,
            "sparse values",
            vv,
            values_offset,
            es,
            sparse_count,
            layout.element_bytes(),
        )?;
    }
    Ok(SparseDef {
        count: sparse_count,
        indices_view,
        indices_offset,
        indices_component,
        values_view,
        values_offset,
    })
}

/// Read access to the loaded buffers through validated views.
pub(crate) struct Reader<'a> {
    pub(crate) views: &'a [ViewDef],
    /// Buffer data (`None`: no data, e.g. a placeholder buffer without `uri`).
    pub(crate) buffers: &'a [Option<Vec<u8>>],
}

impl Reader<'_> {
    /// The bytes of bufferView `index`.
    pub(crate) fn view_bytes(&self, index: usize, ptr: &str) -> Result<&[u8], SceneError> {
        let v = self
            .views
            .get(index)
            .ok_or_else(|| SceneError::invalid(ptr, format!("unresolved bufferView {index}")))?;
        let data = self
            .buffers
            .get(v.buffer)
            .and_then(Option::as_deref)
            .ok_or_else(|| {
                SceneError::invalid(ptr, format!("buffer {} has no data to read", v.buffer))
            })?;
        let start = usize::try_from(v.offset).ok();
        let end = v
            .offset
            .checked_add(v.length)
            .and_then(|e| usize::try_from(e).ok());
        start
            .zip(end)
            .and_then(|(s, e)| data.get(s..e))
            .ok_or_else(|| SceneError::invalid(ptr, "bufferView outside its buffer's data"))
    }

    /// Calls `f(element_index, element_bytes)` for every base element (not the sparse ones).
    fn for_each_base(
        &self,
        acc: &AccessorDef,
        layout: Layout,
        mut f: impl FnMut(usize, &[u8]) -> Result<(), SceneError>,
    ) -> Result<(), SceneError> {
        let Some(view) = acc.view else {
            return Ok(());
        };
        let bytes = self.view_bytes(view, &acc.ptr)?;
        let stride = self.views.get(view).and_then(|v| v.stride);
        let stride = stride.unwrap_or(layout.element_size());
        let es = to_usize(layout.element_bytes())?;
        let (stride, offset) = (to_usize(stride)?, to_usize(acc.offset)?);
        for i in 0..to_usize(acc.count)? {
            let start = i
                .checked_mul(stride)
                .and_then(|s| s.checked_add(offset))
                .ok_or_else(|| SceneError::invalid(&acc.ptr, "offset overflow"))?;
            let el = slice_at(bytes, start, es)
                .ok_or_else(|| SceneError::invalid(&acc.ptr, "element outside its bufferView"))?;
            f(i, el)?;
        }
        Ok(())
    }

    /// The sparse indices, checked strictly increasing and below `count`.
    fn sparse_indices(&self, acc: &AccessorDef, s: &SparseDef) -> Result<Vec<usize>, SceneError> {
        let ptr = format!("{}/sparse/indices", acc.ptr);
        let bytes = self.view_bytes(s.indices_view, &ptr)?;
        let size = to_usize(s.indices_component.size())?;
        let offset = to_usize(s.indices_offset)?;
        let n = to_usize(s.count)?;
        let mut out = Vec::with_capacity(n);
        let mut prev: Option<u32> = None;
        for i in 0..n {
            let at = i.checked_mul(size).and_then(|x| x.checked_add(offset));
            let b = at
                .and_then(|at| slice_at(bytes, at, size))
                .ok_or_else(|| SceneError::invalid(&ptr, "sparse index outside its bufferView"))?;
            let idx = s
                .indices_component
                .read_u32(b)
                .ok_or_else(|| SceneError::invalid(&ptr, "sparse index type"))?;
            if prev.is_some_and(|p| idx <= p) {
                return Err(SceneError::invalid(
                    &ptr,
                    format!("sparse index {i} does not exceed the one before it"),
                ));
            }
            if u64::from(idx) >= acc.count {
                return Err(SceneError::invalid(
                    &ptr,
                    format!(
                        "sparse index {i} is not below the accessor count {}",
                        acc.count
                    ),
                ));
            }
            prev = Some(idx);
            out.push(to_usize(u64::from(idx))?);
        }
        Ok(out)
    }

    /// Calls `f(element_index, element_bytes)` for every sparse substitution.
    fn for_each_sparse(
        &self,
        acc: &AccessorDef,
        layout: Layout,
        mut f: impl FnMut(usize, &[u8]) -> Result<(), SceneError>,
    ) -> Result<(), SceneError> {
        let Some(s) = &acc.sparse else {
            return Ok(());
        };
        let indices = self.sparse_indices(acc, s)?;
        let ptr = format!("{}/sparse/values", acc.ptr);
        let bytes = self.view_bytes(s.values_view, &ptr)?;
        let es = to_usize(layout.element_size())?;
        let real = to_usize(layout.element_bytes())?;
        let offset = to_usize(s.values_offset)?;
        for (i, &target) in indices.iter().enumerate() {
            let at = i.checked_mul(es).and_then(|x| x.checked_add(offset));
            let el = at
                .and_then(|at| slice_at(bytes, at, real))
                .ok_or_else(|| SceneError::invalid(&ptr, "sparse value outside its bufferView"))?;
            f(target, el)?;
        }
        Ok(())
    }

    /// Checks the accessor's data without keeping it: sparse indices ordered and in range, float
    /// components finite, every component within the declared `min`/`max` (which renderers use
    /// for bounding volumes: data outside them would be culled wrongly).
    pub(crate) fn validate(&self, acc: &AccessorDef) -> Result<(), SceneError> {
        let Some(layout) = acc.layout else {
            return Ok(());
        };
        let n = layout.element.components();
        // With sparse substitution, a base element may be replaced: check the final values.
        let replaced: BTreeSet<usize> = match &acc.sparse {
            Some(s) => self.sparse_indices(acc, s)?.into_iter().collect(),
            None => BTreeSet::new(),
        };
        let check = |i: usize, el: &[u8]| -> Result<(), SceneError> {
            for j in 0..n {
                let at = to_usize(layout.component_offset(j as u64))?;
                let b = el.get(at..).unwrap_or_default();
                let v = match layout.component {
                    ComponentType::U32 => f64::from(layout.component.read_u32(b).unwrap_or(0)),
                    c => f64::from(c.read_f32(b, false)),
                };
                if !v.is_finite() {
                    return Err(SceneError::invalid(
                        &acc.ptr,
                        format!("element {i} component {j} is not finite"),
                    ));
                }
                let as_declared = |d: f64| {
                    #[allow(clippy::cast_possible_truncation)]
                    if layout.component == ComponentType::F32 {
                        f64::from(d as f32)
                    } else {
                        d
                    }
                };
                if let Some(&lo) = acc.min.as_ref().and_then(|m| m.get(j))
                    && v < as_declared(lo)
                {
                    return Err(SceneError::invalid(
                        &acc.ptr,
                        format!("element {i} component {j} is below the declared min {lo}"),
                    ));
                }
                if let Some(&hi) = acc.max.as_ref().and_then(|m| m.get(j))
                    && v > as_declared(hi)
                {
                    return Err(SceneError::invalid(
                        &acc.ptr,
                        format!("element {i} component {j} is above the declared max {hi}"),
                    ));
                }
            }
            Ok(())
        };
        self.for_each_base(acc, layout, |i, el| {
            if replaced.contains(&i) {
                Ok(())
            } else {
                check(i, el)
            }
        })?;
        self.for_each_sparse(acc, layout, check)
    }

    /// Reads every element as `N` floats (normalised per the accessor's flag), sparse applied.
    /// `N` must equal the accessor's component count.
    pub(crate) fn read_f32<const N: usize>(
        &self,
        acc: &AccessorDef,
    ) -> Result<Vec<[f32; N]>, SceneError> {
        let layout = acc.layout()?;
        if layout.element.components() != N {
            return Err(SceneError::invalid(
                &acc.ptr,
                format!("expected a {N}-component accessor"),
            ));
        }
        let mut out = vec![[0.0f32; N]; to_usize(acc.count)?];
        let decode = |el: &[u8]| -> Result<[f32; N], SceneError> {
            let mut v = [0.0f32; N];
            for (j, slot) in v.iter_mut().enumerate() {
                let at = to_usize(layout.component_offset(j as u64))?;
                *slot = layout
                    .component
                    .read_f32(el.get(at..).unwrap_or_default(), acc.normalized);
                if !slot.is_finite() {
                    return Err(SceneError::invalid(&acc.ptr, "a non-finite value"));
                }
            }
            Ok(v)
        };
        self.for_each_base(acc, layout, |i, el| {
            if let Some(slot) = out.get_mut(i) {
                *slot = decode(el)?;
            }
            Ok(())
        })?;
        self.for_each_sparse(acc, layout, |i, el| {
            if let Some(slot) = out.get_mut(i) {
                *slot = decode(el)?;
            }
            Ok(())
        })?;
        Ok(out)
    }

    /// Reads a scalar unsigned-integer accessor exactly (indices).
    pub(crate) fn read_u32(&self, acc: &AccessorDef) -> Result<Vec<u32>, SceneError> {
        let layout = acc.layout()?;
        if layout.element != ElementType::Scalar {
            return Err(SceneError::invalid(&acc.ptr, "expected a SCALAR accessor"));
        }
        let mut out = vec![0u32; to_usize(acc.count)?];
        let decode = |el: &[u8]| {
            layout.component.read_u32(el).ok_or_else(|| {
                SceneError::invalid(&acc.ptr, "expected an unsigned integer component type")
            })
        };
        self.for_each_base(acc, layout, |i, el| {
            if let Some(slot) = out.get_mut(i) {
                *slot = decode(el)?;
            }
            Ok(())
        })?;
        self.for_each_sparse(acc, layout, |i, el| {
            if let Some(slot) = out.get_mut(i) {
                *slot = decode(el)?;
            }
            Ok(())
        })?;
        Ok(out)
    }
}

/// `bytes[start..start + len]` without overflow or panic.
fn slice_at(bytes: &[u8], start: usize, len: usize) -> Option<&[u8]> {
    bytes.get(start..start.checked_add(len)?)
}

fn to_usize(v: u64) -> Result<usize, SceneError> {
    usize::try_from(v).map_err(|_| SceneError::invalid("", "size does not fit memory"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalisation_formulas() {
        assert_eq!(ComponentType::I8.read_f32(&[0x80], true), -1.0);
        assert_eq!(ComponentType::I8.read_f32(&[127], true), 1.0);
        assert_eq!(ComponentType::U8.read_f32(&[255], true), 1.0);
        assert_eq!(
            ComponentType::I16.read_f32(&0x8000u16.to_le_bytes(), true),
            -1.0
        );
        assert_eq!(ComponentType::U16.read_f32(&[0xff, 0xff], true), 1.0);
        assert_eq!(ComponentType::U16.read_f32(&[2, 0], false), 2.0);
    }

    #[test]
    fn matrix_columns_are_padded() {
        let mat3_u8 = Layout {
            component: ComponentType::U8,
            element: ElementType::Mat3,
        };
        assert_eq!(mat3_u8.element_size(), 12);
        assert_eq!(mat3_u8.component_offset(3), 4);
        let mat2_i16 = Layout {
            component: ComponentType::I16,
            element: ElementType::Mat2,
        };
        assert_eq!(mat2_i16.element_size(), 8);
        let mat3_i16 = Layout {
            component: ComponentType::I16,
            element: ElementType::Mat3,
        };
        assert_eq!(mat3_i16.element_size(), 24);
        // The last element ends at its last real byte (the validator's element lengths).
        assert_eq!(mat3_u8.element_bytes(), 11);
        assert_eq!(mat3_i16.element_bytes(), 22);
        let mat2_u8 = Layout {
            component: ComponentType::U8,
            element: ElementType::Mat2,
        };
        assert_eq!((mat2_u8.element_size(), mat2_u8.element_bytes()), (8, 6));
        assert_eq!(mat2_i16.element_bytes(), 8);
        let vec3_u8 = Layout {
            component: ComponentType::U8,
            element: ElementType::Vec3,
        };
        assert_eq!((vec3_u8.element_size(), vec3_u8.element_bytes()), (3, 3));
    }
}
