//! Strided views of `f64` buffers, built safely from slices, and sets of output points.
//!
//! A view is what the C API calls `bs_cview` / `bs_view`: element `k` lives at `k * stride`
//! elements from element 0. Strides here count elements (the C side counts bytes; the crate
//! converts). A view can only be made from a slice it borrows, so it never reaches outside it.

use std::marker::PhantomData;

use crate::error::{Error, Result};
use crate::sys;

const F64_BYTES: isize = std::mem::size_of::<f64>() as isize;

/// Number of elements `0, stride, 2*stride, ...` that fit in `len` (a stride of 0 panics).
fn strided_len(len: usize, stride: usize) -> usize {
    assert!(stride > 0, "stride must be at least 1");
    len.div_ceil(stride)
}

/// A read-only strided view of `f64` values (the C `bs_cview`).
#[derive(Debug, Clone, Copy)]
pub struct Strided<'a> {
    ptr: *const f64,
    len: usize,
    stride: isize,
    marker: PhantomData<&'a [f64]>,
}

// SAFETY: a Strided is a shared borrow of f64 values, exactly like &[f64].
unsafe impl Send for Strided<'_> {}
unsafe impl Sync for Strided<'_> {}

impl<'a> Strided<'a> {
    /// Every `stride`-th element of `data`, starting with `data[0]`.
    /// `Strided::new(&xyz[1..], 3)` is the y coordinates of interleaved xyz points.
    ///
    /// # Panics
    /// If `stride` is 0.
    pub fn new(data: &'a [f64], stride: usize) -> Strided<'a> {
        let len = strided_len(data.len(), stride);
        Strided { ptr: data.as_ptr(), len, stride: stride as isize, marker: PhantomData }
    }

    /// The same elements in reverse order (a negative stride for the C library).
    pub fn rev(self) -> Strided<'a> {
        if self.len == 0 {
            return self;
        }
        // SAFETY: element len-1 lies inside the borrowed slice.
        let last = unsafe { self.ptr.offset((self.len as isize - 1) * self.stride) };
        Strided { ptr: last, len: self.len, stride: -self.stride, marker: PhantomData }
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True if the view has no elements.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Element `i`, or `None` past the end.
    pub fn get(&self, i: usize) -> Option<f64> {
        // SAFETY: i < len, so the element lies inside the borrowed slice.
        (i < self.len).then(|| unsafe { *self.ptr.offset(i as isize * self.stride) })
    }

    /// The elements in order.
    pub fn iter(&self) -> impl Iterator<Item = f64> + 'a {
        let view = *self;
        (0..view.len).map(move |i| view.get(i).unwrap_or(f64::NAN))
    }

    pub(crate) fn as_cview(&self) -> sys::bs_cview {
        sys::bs_cview { data: self.ptr, count: self.len, stride: self.stride * F64_BYTES }
    }
}

impl<'a> From<&'a [f64]> for Strided<'a> {
    fn from(data: &'a [f64]) -> Strided<'a> {
        Strided::new(data, 1)
    }
}

impl<'a> From<&'a Vec<f64>> for Strided<'a> {
    fn from(data: &'a Vec<f64>) -> Strided<'a> {
        Strided::new(data, 1)
    }
}

impl<'a, const N: usize> From<&'a [f64; N]> for Strided<'a> {
    fn from(data: &'a [f64; N]) -> Strided<'a> {
        Strided::new(data, 1)
    }
}

/// A writable strided view of `f64` values (the C `bs_view`).
#[derive(Debug)]
pub struct StridedMut<'a> {
    ptr: *mut f64,
    len: usize,
    stride: isize,
    marker: PhantomData<&'a mut [f64]>,
}

// SAFETY: a StridedMut is an exclusive borrow of f64 values, exactly like &mut [f64].
unsafe impl Send for StridedMut<'_> {}
unsafe impl Sync for StridedMut<'_> {}

impl<'a> StridedMut<'a> {
    /// Every `stride`-th element of `data`, starting with `data[0]`.
    /// `StridedMut::new(&mut xyz[1..], 3)` is the y coordinates of interleaved xyz points.
    ///
    /// # Panics
    /// If `stride` is 0.
    pub fn new(data: &'a mut [f64], stride: usize) -> StridedMut<'a> {
        let len = strided_len(data.len(), stride);
        StridedMut { ptr: data.as_mut_ptr(), len, stride: stride as isize, marker: PhantomData }
    }

    /// Splits interleaved data (`x0 y0 z0 x1 y1 z1 ...` for `N = 3`) into `N` disjoint views,
    /// one per component, each of `data.len() / N` elements.
    ///
    /// # Panics
    /// If `N` is 0.
    pub fn split_interleaved<const N: usize>(data: &'a mut [f64]) -> [StridedMut<'a>; N] {
        assert!(N > 0, "at least one component");
        let len = data.len() / N;
        let base = data.as_mut_ptr();
        // SAFETY: component c uses indices c + k*N for k < len, all below data.len(), and the
        // components are pairwise disjoint, so the N views never alias.
        std::array::from_fn(|c| StridedMut {
            ptr: unsafe { base.add(c) },
            len,
            stride: N as isize,
            marker: PhantomData,
        })
    }

    /// The same elements in reverse order (a negative stride for the C library).
    pub fn rev(self) -> StridedMut<'a> {
        if self.len == 0 {
            return self;
        }
        // SAFETY: element len-1 lies inside the borrowed slice.
        let last = unsafe { self.ptr.offset((self.len as isize - 1) * self.stride) };
        StridedMut { ptr: last, len: self.len, stride: -self.stride, marker: PhantomData }
    }

    /// A shorter-lived view of the same elements, so the view can be used again afterwards.
    pub fn reborrow(&mut self) -> StridedMut<'_> {
        StridedMut { ptr: self.ptr, len: self.len, stride: self.stride, marker: PhantomData }
    }

    /// A read-only view of the same elements.
    pub fn as_strided(&self) -> Strided<'_> {
        Strided { ptr: self.ptr, len: self.len, stride: self.stride, marker: PhantomData }
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True if the view has no elements.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Element `i`, or `None` past the end.
    pub fn get(&self, i: usize) -> Option<f64> {
        self.as_strided().get(i)
    }

    /// Writes element `i`; returns false (writing nothing) past the end.
    pub fn set(&mut self, i: usize, value: f64) -> bool {
        if i >= self.len {
            return false;
        }
        // SAFETY: i < len, so the element lies inside the exclusively borrowed slice.
        unsafe { *self.ptr.offset(i as isize * self.stride) = value };
        true
    }

    pub(crate) fn as_view(&mut self) -> sys::bs_view {
        sys::bs_view { data: self.ptr, count: self.len, stride: self.stride * F64_BYTES }
    }
}

impl<'a> From<&'a mut [f64]> for StridedMut<'a> {
    fn from(data: &'a mut [f64]) -> StridedMut<'a> {
        StridedMut::new(data, 1)
    }
}

/// Where a set of output points goes: interleaved in one slice, or one view per coordinate.
///
/// Made with `From` from `&mut [f64]`, `&mut Vec<f64>` or `&mut [f64; N]` (interleaved: point
/// `k` coordinate `c` at index `k * dim + c`, `len / dim` points fit) or from an array or `Vec` of
/// [`StridedMut`] views (structure of arrays; there must be exactly one view per coordinate).
#[derive(Debug)]
pub struct PointsMut<'a> {
    repr: Repr<'a>,
}

#[derive(Debug)]
enum Repr<'a> {
    Interleaved(&'a mut [f64]),
    Views(Vec<StridedMut<'a>>),
}

impl<'a> PointsMut<'a> {
    /// Points stored interleaved: point `k` coordinate `c` at `data[k * dim + c]`.
    pub fn interleaved(data: &'a mut [f64]) -> PointsMut<'a> {
        PointsMut { repr: Repr::Interleaved(data) }
    }

    /// Points stored as one view per coordinate.
    pub fn views(views: impl IntoIterator<Item = StridedMut<'a>>) -> PointsMut<'a> {
        PointsMut { repr: Repr::Views(views.into_iter().collect()) }
    }

    /// The C views for points of dimension `dim`: the first `dim` entries are filled.
    /// A view set whose length differs from `dim` is `Dimension`.
    pub(crate) fn c_views(&mut self, dim: usize) -> Result<[sys::bs_view; sys::BS_MAX_DIM]> {
        let empty = sys::bs_view { data: std::ptr::null_mut(), count: 0, stride: 0 };
        let mut out = [empty; sys::BS_MAX_DIM];
        if dim == 0 || dim > sys::BS_MAX_DIM {
            return Err(Error::from_code(sys::BS_ERR_DIMENSION));
        }
        match &mut self.repr {
            Repr::Interleaved(data) => {
                let len = data.len() / dim;
                let base = data.as_mut_ptr();
                for (c, view) in out.iter_mut().take(dim).enumerate() {
                    // Coordinate c of point k is data[k * dim + c] < data.len() for k < len.
                    // When len is 0 the library never reads the pointer (count is 0), hence
                    // wrapping_add rather than add.
                    *view = sys::bs_view {
                        data: base.wrapping_add(c),
                        count: len,
                        stride: dim as isize * F64_BYTES,
                    };
                }
            }
            Repr::Views(views) => {
                if views.len() != dim {
                    return Err(Error::from_code(sys::BS_ERR_DIMENSION));
                }
                for (view, v) in out.iter_mut().zip(views.iter_mut()) {
                    *view = v.as_view();
                }
            }
        }
        Ok(out)
    }
}

impl<'a> From<&'a mut [f64]> for PointsMut<'a> {
    fn from(data: &'a mut [f64]) -> PointsMut<'a> {
        PointsMut::interleaved(data)
    }
}

impl<'a> From<&'a mut Vec<f64>> for PointsMut<'a> {
    fn from(data: &'a mut Vec<f64>) -> PointsMut<'a> {
        PointsMut::interleaved(data)
    }
}

impl<'a, const N: usize> From<&'a mut [f64; N]> for PointsMut<'a> {
    fn from(data: &'a mut [f64; N]) -> PointsMut<'a> {
        PointsMut::interleaved(data)
    }
}

impl<'a, const N: usize> From<[StridedMut<'a>; N]> for PointsMut<'a> {
    fn from(views: [StridedMut<'a>; N]) -> PointsMut<'a> {
        PointsMut::views(views)
    }
}

impl<'a> From<Vec<StridedMut<'a>>> for PointsMut<'a> {
    fn from(views: Vec<StridedMut<'a>>) -> PointsMut<'a> {
        PointsMut::views(views)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strided_reads_every_stride_th_element() {
        let data = [0., 1., 2., 3., 4., 5., 6.];
        let s = Strided::new(&data[1..], 3);
        assert_eq!(s.len(), 2);
        assert_eq!(s.iter().collect::<Vec<_>>(), [1., 4.]);
        assert_eq!(s.get(2), None);
        assert_eq!(s.rev().iter().collect::<Vec<_>>(), [4., 1.]);
        let c = s.rev().as_cview();
        assert_eq!((c.count, c.stride), (2, -24));
        assert_eq!(Strided::new(&data, 1).len(), 7);
        assert!(Strided::new(&[], 4).is_empty());
    }

    #[test]
    #[should_panic(expected = "stride")]
    fn zero_stride_panics() {
        let _ = Strided::new(&[1.0], 0);
    }

    #[test]
    fn interleaved_split_is_disjoint_and_covers_whole_points() {
        let mut xyz = [0.0; 7];
        let [mut x, mut y, mut z] = StridedMut::split_interleaved::<3>(&mut xyz);
        assert_eq!((x.len(), y.len(), z.len()), (2, 2, 2));
        for k in 0..2 {
            x.set(k, 1.0 + k as f64);
            y.set(k, 10.0 + k as f64);
            z.set(k, 100.0 + k as f64);
        }
        assert!(!z.set(2, -1.0));
        assert_eq!(xyz, [1., 10., 100., 2., 11., 101., 0.]);
    }

    #[test]
    fn points_views_check_their_dimension() {
        let mut buf = [0.0; 10];
        let mut p = PointsMut::from(&mut buf[..]);
        let v = p.c_views(3).unwrap();
        assert_eq!((v[2].count, v[2].stride), (3, 24));
        assert_eq!(p.c_views(0).unwrap_err().kind(), crate::ErrorKind::Dimension);
        let mut a = [0.0; 2];
        let mut b = [0.0; 2];
        let mut q = PointsMut::from([StridedMut::from(&mut a[..]), StridedMut::from(&mut b[..])]);
        assert!(q.c_views(2).is_ok());
        assert_eq!(q.c_views(3).unwrap_err().kind(), crate::ErrorKind::Dimension);
    }
}
