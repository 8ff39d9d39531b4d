//! Bounds-checked reads of glTF accessors.
//!
//! The `gltf` crate's `Reader` is not used: it computes
//! `offset + stride·(count − 1) + size` unchecked (overflow, and underflow
//! for `count = 0`, panic in debug builds), and only `debug_assert`s that
//! the accessor's type matches the one read. Here every accessor's type is
//! checked, and its byte range against its buffer view, and the view's
//! against its buffer, with checked arithmetic, before anything is
//! allocated; so an allocation never exceeds the bytes present.

use std::borrow::Cow;

use ::gltf::Accessor;
use ::gltf::accessor::{DataType, Dimensions};
use glam::DVec3;

/// Where an accessor's elements lie.
struct Layout<'b> {
    /// The buffer view's bytes.
    view: &'b [u8],
    /// Offset of the first element in the view.
    start: usize,
    /// Bytes from one element to the next.
    stride: usize,
    /// Bytes per element.
    size: usize,
    /// Number of elements.
    count: usize,
}

impl<'b> Layout<'b> {
    /// Locates `accessor`'s elements of `size` bytes, checking every bound.
    fn new(
        accessor: &Accessor<'_>,
        size: usize,
        buffers: &'b [Cow<'_, [u8]>],
    ) -> Result<Self, String> {
        let a = accessor.index();
        if accessor.sparse().is_some() {
            return Err(format!("accessor {a} is sparse, which is not supported"));
        }
        let view = accessor
            .view()
            .ok_or_else(|| format!("accessor {a} has no buffer view"))?;
        let b = view.buffer().index();
        let buffer = buffers
            .get(b)
            .ok_or_else(|| format!("buffer {b} was not loaded"))?;
        let (offset, length) = (view.offset(), view.length());
        let bytes = offset
            .checked_add(length)
            .and_then(|end| buffer.get(offset..end))
            .ok_or_else(|| {
                format!(
                    "buffer view {} (bytes {offset}..{offset}+{length}) reaches past the end \
                     of buffer {b} ({} bytes)",
                    view.index(),
                    buffer.len()
                )
            })?;
        let stride = view.stride().unwrap_or(size);
        if stride < size {
            return Err(format!(
                "buffer view {} has stride {stride}, less than accessor {a}'s element size {size}",
                view.index()
            ));
        }
        let (start, count) = (accessor.offset(), accessor.count());
        let end = count
            .checked_sub(1)
            .map_or(Some(start), |last| {
                last.checked_mul(stride)
                    .and_then(|x| x.checked_add(start))
                    .and_then(|x| x.checked_add(size))
            })
            .filter(|&end| end <= bytes.len());
        if end.is_none() {
            return Err(format!(
                "accessor {a} ({count} elements of {size} bytes, stride {stride}, offset {start}) \
                 reaches past the end of buffer view {} ({} bytes)",
                view.index(),
                bytes.len()
            ));
        }
        Ok(Self {
            view: bytes,
            start,
            stride,
            size,
            count,
        })
    }

    /// The bytes of element `i`.
    fn element(&self, i: usize) -> Option<&'b [u8]> {
        let at = self.start + i * self.stride;
        self.view.get(at..at + self.size)
    }

    /// Every element, in order (all in bounds by construction).
    fn elements(&self) -> impl Iterator<Item = &'b [u8]> + '_ {
        (0..self.count).map_while(|i| self.element(i))
    }
}

/// Reads a `POSITION` accessor (`f32` `VEC3`), widened exactly to `f64`.
pub(super) fn positions(
    accessor: &Accessor<'_>,
    buffers: &[Cow<'_, [u8]>],
) -> Result<Vec<DVec3>, String> {
    let a = accessor.index();
    let (kind, dims) = (accessor.data_type(), accessor.dimensions());
    if kind != DataType::F32 || dims != Dimensions::Vec3 || accessor.normalized() {
        return Err(format!(
            "POSITION accessor {a} is {kind:?} {dims:?}, only F32 Vec3 is supported"
        ));
    }
    let layout = Layout::new(accessor, 12, buffers)?;
    let mut out = Vec::with_capacity(layout.count);
    for (i, e) in layout.elements().enumerate() {
        let f = |k: usize| f64::from(f32::from_le_bytes([e[k], e[k + 1], e[k + 2], e[k + 3]]));
        let v = DVec3::new(f(0), f(4), f(8));
        if !v.is_finite() {
            return Err(format!(
                "POSITION accessor {a} element {i} has a non-finite coordinate {v}"
            ));
        }
        out.push(v);
    }
    Ok(out)
}

/// Reads an index accessor (unsigned 8, 16 or 32-bit `SCALAR`).
pub(super) fn indices(
    accessor: &Accessor<'_>,
    buffers: &[Cow<'_, [u8]>],
) -> Result<Vec<u32>, String> {
    let a = accessor.index();
    let (kind, dims) = (accessor.data_type(), accessor.dimensions());
    let size = match kind {
        DataType::U8 => 1,
        DataType::U16 => 2,
        DataType::U32 => 4,
        _ => 0,
    };
    if size == 0 || dims != Dimensions::Scalar || accessor.normalized() {
        return Err(format!(
            "index accessor {a} is {kind:?} {dims:?}, only unsigned U8, U16 or U32 scalars are supported"
        ));
    }
    let layout = Layout::new(accessor, size, buffers)?;
    Ok(layout
        .elements()
        .map(|e| match *e {
            [x] => u32::from(x),
            [x, y] => u32::from(u16::from_le_bytes([x, y])),
            [x, y, z, w] => u32::from_le_bytes([x, y, z, w]),
            _ => 0, // Unreachable: elements have exactly `size` bytes.
        })
        .collect())
}
