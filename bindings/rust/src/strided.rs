//! Strided views of `f64` buffers, built safely from slices, and sets of output points.
//!
//! A view is what the C API calls `bs_cview` / `bs_view`: element `k` lives at `k * stride`
//! elements from element 0. Strides here count elements (the C side counts bytes; the crate
//! converts). A view can only be made from a slice it borrows, so it never reaches outside it.
//!
//! Invariants of every view (established by [`layout`], relied on by every `unsafe` block here):
//! if `len > 0`, `ptr.offset(i * stride)` is an element of the borrowed slice for every `i < len`;
//! if `len == 0`, `ptr` is the start of the borrowed slice (possibly empty) and is never
//! dereferenced; `|stride| * size_of::<f64>()` fits in `isize` (a view of fewer than two elements
//! keeps the stride 1, which the C library never applies). No pointer is ever computed outside
//! the borrowed slice.

use std::marker::PhantomData;
use std::ops::{Index, IndexMut};

use crate::error::{Error, Result};
use crate::sys;

const F64_BYTES: isize = std::mem::size_of::<f64>() as isize;

/// The length and kept element stride of the view of every `stride`-th element of a slice of
/// `span` elements. Never overflows: `div_ceil` cannot, and a view of two or more elements has
/// `stride <= span - 1`, whose byte count fits in `isize` because the slice's does.
fn layout(span: usize, stride: usize) -> Result<(usize, isize)> {
    if stride == 0 {
        return Err(Error::argument_error(sys::BS_ERR_INVALID_ARG, "stride", "must be at least 1, got 0"));
    }
    let len = span.div_ceil(stride);
    if len < 2 {
        return Ok((len, 1));
    }
    match isize::try_from(stride).ok().filter(|s| s.checked_mul(F64_BYTES).is_some()) {
        Some(s) => Ok((len, s)),
        // Unreachable for a real slice (see above); reported rather than assumed.
        None => Err(Error::argument_error(
            sys::BS_ERR_INVALID_ARG,
            "stride",
            format!("is {stride} elements, too many bytes for isize"),
        )),
    }
}

/// A read-only strided view of `f64` values (the C `bs_cview`).
///
/// ```
/// use bezsurf::Strided;
///
/// let uv = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6]; // interleaved (u, v) pairs
/// let u = Strided::new(&uv, 2);
/// let v = Strided::new(&uv[1..], 2);
/// assert_eq!(u.iter().collect::<Vec<_>>(), [0.1, 0.3, 0.5]);
/// assert_eq!(v[2], 0.6);
/// assert_eq!(v.rev().iter().collect::<Vec<_>>(), [0.6, 0.4, 0.2]);
/// // A stride longer than the slice selects its first element only.
/// assert_eq!(Strided::new(&uv, usize::MAX).len(), 1);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Strided<'a> {
    ptr: *const f64,
    len: usize,
    stride: isize,
    marker: PhantomData<&'a [f64]>,
}

// SAFETY: a Strided is a shared borrow of f64 values, exactly like &[f64], which is Send.
unsafe impl Send for Strided<'_> {}
// SAFETY: as for Send: shared read-only access to f64 values, like &[f64], which is Sync.
unsafe impl Sync for Strided<'_> {}

impl<'a> Strided<'a> {
    /// Every `stride`-th element of `data`, starting with `data[0]`: `data.len().div_ceil(stride)`
    /// elements. `Strided::new(&xyz[1..], 3)` is the y coordinates of interleaved xyz points. Any
    /// stride from 1 to `usize::MAX` is allowed; one longer than the slice gives its first element.
    ///
    /// # Panics
    /// If `stride` is 0 (see [`Strided::try_new`] for the error instead).
    pub fn new(data: &'a [f64], stride: usize) -> Strided<'a> {
        Strided::try_new(data, stride).unwrap_or_else(|e| panic!("Strided::new: {e}"))
    }

    /// As [`Strided::new`], but a stride of 0 is an `InvalidArg` error naming `stride`.
    ///
    /// ```
    /// let err = bezsurf::Strided::try_new(&[1.0, 2.0], 0).unwrap_err();
    /// assert_eq!(err.argument(), Some("stride"));
    /// ```
    pub fn try_new(data: &'a [f64], stride: usize) -> Result<Strided<'a>> {
        let (len, stride) = layout(data.len(), stride)?;
        Ok(Strided { ptr: data.as_ptr(), len, stride, marker: PhantomData })
    }

    /// The same elements in reverse order (a negative stride for the C library).
    pub fn rev(self) -> Strided<'a> {
        if self.len == 0 {
            return self;
        }
        Strided { ptr: self.elem(self.len - 1), len: self.len, stride: -self.stride, marker: PhantomData }
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True if the view has no elements.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Pointer to element `i`, which must be below `len`.
    fn elem(&self, i: usize) -> *const f64 {
        assert!(i < self.len, "index {i} out of range for a view of {} elements", self.len);
        // Cannot overflow: |i * stride| <= (len - 1) * |stride| < the slice's length.
        let offset = i as isize * self.stride;
        // SAFETY: i < len, so by the view's invariant element i lies inside the borrowed slice.
        unsafe { self.ptr.offset(offset) }
    }

    /// Element `i`, or `None` past the end.
    pub fn get(&self, i: usize) -> Option<f64> {
        // SAFETY: i < len, so elem(i) points at an initialised f64 of the borrowed slice.
        (i < self.len).then(|| unsafe { *self.elem(i) })
    }

    /// The elements in order (also `for x in view`).
    pub fn iter(&self) -> StridedIter<'a> {
        StridedIter { view: *self, front: 0, back: self.len }
    }

    pub(crate) fn as_cview(&self) -> sys::bs_cview {
        // Cannot overflow: layout() checked |stride| * 8 against isize.
        sys::bs_cview { data: self.ptr, count: self.len, stride: self.stride * F64_BYTES }
    }
}

/// Iterator over the values of a [`Strided`] view, front to back ([`Strided::iter`]).
#[derive(Debug, Clone)]
pub struct StridedIter<'a> {
    view: Strided<'a>,
    front: usize,
    back: usize,
}

impl Iterator for StridedIter<'_> {
    type Item = f64;
    fn next(&mut self) -> Option<f64> {
        if self.front == self.back {
            return None;
        }
        self.front += 1;
        self.view.get(self.front - 1)
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        (self.back - self.front, Some(self.back - self.front))
    }
}

impl DoubleEndedIterator for StridedIter<'_> {
    fn next_back(&mut self) -> Option<f64> {
        if self.front == self.back {
            return None;
        }
        self.back -= 1;
        self.view.get(self.back)
    }
}

impl ExactSizeIterator for StridedIter<'_> {}
impl std::iter::FusedIterator for StridedIter<'_> {}

impl<'a> IntoIterator for Strided<'a> {
    type Item = f64;
    type IntoIter = StridedIter<'a>;
    fn into_iter(self) -> StridedIter<'a> {
        self.iter()
    }
}

impl Index<usize> for Strided<'_> {
    type Output = f64;
    /// Element `i`.
    ///
    /// # Panics
    /// If `i >= len()`.
    fn index(&self, i: usize) -> &f64 {
        // SAFETY: elem(i) checked i < len, so it points into the slice borrowed for 'a, which
        // outlives &self.
        unsafe { &*self.elem(i) }
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

impl<'a> From<&'a StridedMut<'_>> for Strided<'a> {
    fn from(view: &'a StridedMut<'_>) -> Strided<'a> {
        view.as_strided()
    }
}

/// A writable strided view of `f64` values (the C `bs_view`).
///
/// ```
/// use bezsurf::StridedMut;
///
/// let mut xyz = [0.0; 6];
/// let [mut x, _, mut z] = StridedMut::split_interleaved::<3>(&mut xyz);
/// x[1] = 1.0;
/// assert!(z.set(0, 5.0));
/// assert!(!z.set(2, 5.0)); // past the end: nothing written
/// assert_eq!(xyz, [0.0, 0.0, 5.0, 1.0, 0.0, 0.0]);
/// ```
#[derive(Debug)]
pub struct StridedMut<'a> {
    ptr: *mut f64,
    len: usize,
    stride: isize,
    marker: PhantomData<&'a mut [f64]>,
}

// SAFETY: a StridedMut is an exclusive borrow of f64 values, exactly like &mut [f64], which is Send.
unsafe impl Send for StridedMut<'_> {}
// SAFETY: through &StridedMut only reads are possible (get, as_strided), like &&mut [f64].
unsafe impl Sync for StridedMut<'_> {}

impl<'a> StridedMut<'a> {
    /// Every `stride`-th element of `data`, starting with `data[0]`.
    /// `StridedMut::new(&mut xyz[1..], 3)` is the y coordinates of interleaved xyz points. Any
    /// stride from 1 to `usize::MAX` is allowed; one longer than the slice gives its first element.
    ///
    /// # Panics
    /// If `stride` is 0 (see [`StridedMut::try_new`] for the error instead).
    pub fn new(data: &'a mut [f64], stride: usize) -> StridedMut<'a> {
        StridedMut::try_new(data, stride).unwrap_or_else(|e| panic!("StridedMut::new: {e}"))
    }

    /// As [`StridedMut::new`], but a stride of 0 is an `InvalidArg` error naming `stride`.
    pub fn try_new(data: &'a mut [f64], stride: usize) -> Result<StridedMut<'a>> {
        let (len, stride) = layout(data.len(), stride)?;
        Ok(StridedMut { ptr: data.as_mut_ptr(), len, stride, marker: PhantomData })
    }

    /// Splits interleaved data (`x0 y0 z0 x1 y1 z1 ...` for `N = 3`) into `N` disjoint views,
    /// one per component, each of `data.len() / N` elements (a trailing partial point is left
    /// out; a slice shorter than `N` gives `N` empty views).
    ///
    /// # Panics
    /// If `N` is 0.
    pub fn split_interleaved<const N: usize>(data: &'a mut [f64]) -> [StridedMut<'a>; N] {
        assert!(N > 0, "split_interleaved needs at least one component (N > 0)");
        let len = data.len() / N;
        // len >= 1 only if data.len() >= N >= 2 or N == 1; in both cases the stride N is below
        // the slice's length or the view has one element.
        let stride = if len < 2 { 1 } else { N as isize };
        let base = data.as_mut_ptr();
        std::array::from_fn(|c| {
            let ptr = if len == 0 {
                // Empty views keep the slice's own start, which is always a valid pointer.
                base
            } else {
                // SAFETY: len >= 1 means data.len() >= N > c, so base + c is inside the slice.
                unsafe { base.add(c) }
            };
            // Component c uses indices c + k*N for k < len, all below len*N <= data.len(), and
            // the components are pairwise disjoint, so the N views never alias.
            StridedMut { ptr, len, stride, marker: PhantomData }
        })
    }

    /// The same elements in reverse order (a negative stride for the C library).
    pub fn rev(self) -> StridedMut<'a> {
        if self.len == 0 {
            return self;
        }
        let last = self.as_strided().elem(self.len - 1) as *mut f64;
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
        self[i] = value;
        true
    }

    pub(crate) fn as_view(&mut self) -> sys::bs_view {
        // Cannot overflow: layout() checked |stride| * 8 against isize.
        sys::bs_view { data: self.ptr, count: self.len, stride: self.stride * F64_BYTES }
    }
}

impl Index<usize> for StridedMut<'_> {
    type Output = f64;
    /// Element `i`.
    ///
    /// # Panics
    /// If `i >= len()`.
    fn index(&self, i: usize) -> &f64 {
        // SAFETY: elem(i) checked i < len, so it points into the slice borrowed for 'a, and
        // &self keeps every writer away while the reference lives.
        unsafe { &*self.as_strided().elem(i) }
    }
}

impl IndexMut<usize> for StridedMut<'_> {
    /// Element `i`, writable.
    ///
    /// # Panics
    /// If `i >= len()`.
    fn index_mut(&mut self, i: usize) -> &mut f64 {
        let p = self.as_strided().elem(i) as *mut f64;
        // SAFETY: elem(i) checked i < len, so p points into the slice exclusively borrowed for
        // 'a; &mut self makes this the only reference to it while it lives.
        unsafe { &mut *p }
    }
}

impl<'a> From<&'a mut [f64]> for StridedMut<'a> {
    fn from(data: &'a mut [f64]) -> StridedMut<'a> {
        StridedMut::new(data, 1)
    }
}

impl<'a> From<&'a mut Vec<f64>> for StridedMut<'a> {
    fn from(data: &'a mut Vec<f64>) -> StridedMut<'a> {
        StridedMut::new(data, 1)
    }
}

impl<'a, const N: usize> From<&'a mut [f64; N]> for StridedMut<'a> {
    fn from(data: &'a mut [f64; N]) -> StridedMut<'a> {
        StridedMut::new(data, 1)
    }
}

/// Where a set of output points goes: interleaved in one slice, or one view per coordinate.
///
/// Made with `From` from `&mut [f64]`, `&mut Vec<f64>` or `&mut [f64; N]` (interleaved: point
/// `k` coordinate `c` at index `k * dim + c`, `len / dim` points fit) or from an array or `Vec` of
/// [`StridedMut`] views (structure of arrays; there must be exactly one view per coordinate).
///
/// ```
/// use bezsurf::{Patch, PointsMut, StridedMut};
///
/// let line = Patch::new(1, 0, 2, &[0.0, 0.0, 4.0, 2.0])?; // from (0, 0) to (4, 2)
/// let (mut x, mut y) = ([0.0; 2], [0.0; 2]);
/// let soa = PointsMut::views([StridedMut::from(&mut x), StridedMut::from(&mut y)]);
/// line.eval(&[0.5, 1.0], &[0.0, 0.0], soa)?;
/// assert_eq!((x, y), ([2.0, 4.0], [1.0, 2.0]));
/// # Ok::<(), bezsurf::Error>(())
/// ```
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

    /// How many points of dimension `dim` (at least 1) fit.
    pub(crate) fn capacity(&self, dim: usize) -> usize {
        match &self.repr {
            Repr::Interleaved(data) => data.len() / dim.max(1),
            Repr::Views(views) => views.iter().map(StridedMut::len).min().unwrap_or(0),
        }
    }

    /// The C views for points of dimension `dim`: the first `dim` entries are filled.
    /// A view set whose length differs from `dim` is `Dimension`, attributed to `name`.
    pub(crate) fn c_views(
        &mut self,
        dim: usize,
        name: &'static str,
    ) -> Result<[sys::bs_view; sys::BS_MAX_DIM]> {
        let empty = sys::bs_view { data: std::ptr::null_mut(), count: 0, stride: 0 };
        let mut out = [empty; sys::BS_MAX_DIM];
        if dim == 0 || dim > sys::BS_MAX_DIM {
            return Err(Error::argument_error(
                sys::BS_ERR_DIMENSION,
                name,
                format!("is for points of dimension {dim}; 1 to {} are possible", sys::BS_MAX_DIM),
            ));
        }
        match &mut self.repr {
            Repr::Interleaved(data) => {
                let len = data.len() / dim;
                let base = data.as_mut_ptr();
                // dim <= BS_MAX_DIM, so this cannot overflow.
                let stride = dim as isize * F64_BYTES;
                for (c, view) in out.iter_mut().take(dim).enumerate() {
                    let data = if len == 0 {
                        // No point fits: the library reads no pointer of a zero-count view,
                        // and the slice's own start is always a valid one.
                        base
                    } else {
                        // SAFETY: len >= 1 means data.len() >= dim > c, so base + c is inside
                        // the slice; coordinate c of point k is data[k * dim + c] < data.len()
                        // for every k < len.
                        unsafe { base.add(c) }
                    };
                    *view = sys::bs_view { data, count: len, stride };
                }
            }
            Repr::Views(views) => {
                if views.len() != dim {
                    return Err(Error::argument_error(
                        sys::BS_ERR_DIMENSION,
                        name,
                        format!("has {} views for points of dimension {dim}", views.len()),
                    ));
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

impl<'a> FromIterator<StridedMut<'a>> for PointsMut<'a> {
    fn from_iter<I: IntoIterator<Item = StridedMut<'a>>>(views: I) -> PointsMut<'a> {
        PointsMut::views(views)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The address range [lo, hi) of a slice, to check that views stay inside it.
    fn range(data: &[f64]) -> (usize, usize) {
        let lo = data.as_ptr() as usize;
        (lo, lo + std::mem::size_of_val(data))
    }

    /// Every element address of a C view, checked to lie inside [lo, hi) (an empty view's
    /// pointer must be lo itself).
    fn assert_inside(data: *const f64, count: usize, stride: isize, (lo, hi): (usize, usize)) {
        if count == 0 {
            assert_eq!(data as usize, lo, "an empty view keeps the slice's start");
            return;
        }
        assert_eq!(stride % F64_BYTES, 0);
        for k in 0..count {
            let addr = data as isize + k as isize * stride;
            assert!(addr as usize >= lo && (addr as usize) + 8 <= hi, "element {k} outside the slice");
        }
    }

    #[test]
    fn strided_reads_every_stride_th_element() {
        let data = [0., 1., 2., 3., 4., 5., 6.];
        let s = Strided::new(&data[1..], 3);
        assert_eq!(s.len(), 2);
        assert_eq!(s.iter().collect::<Vec<_>>(), [1., 4.]);
        assert_eq!(s.get(2), None);
        assert_eq!(s.rev().iter().collect::<Vec<_>>(), [4., 1.]);
        assert_eq!(s.iter().rev().collect::<Vec<_>>(), [4., 1.]);
        let mut it = s.into_iter();
        assert_eq!(
            (it.len(), it.next(), it.len(), it.next_back(), it.next()),
            (2, Some(1.), 1, Some(4.), None)
        );
        let c = s.rev().as_cview();
        assert_eq!((c.count, c.stride), (2, -24));
        assert_eq!(Strided::new(&data, 1).len(), 7);
        assert!(Strided::new(&[], 4).is_empty());
    }

    #[test]
    #[should_panic(expected = "argument `stride` must be at least 1")]
    fn zero_stride_panics_naming_the_stride() {
        let _ = Strided::new(&[1.0], 0);
    }

    #[test]
    fn zero_stride_is_an_error_naming_the_stride() {
        let e = Strided::try_new(&[1.0], 0).unwrap_err();
        assert_eq!((e.kind(), e.argument()), (crate::ErrorKind::InvalidArg, Some("stride")));
        let mut d = [1.0];
        assert_eq!(StridedMut::try_new(&mut d, 0).unwrap_err().argument(), Some("stride"));
    }

    #[test]
    fn huge_strides_give_one_element_and_a_small_byte_stride() {
        let data = [7.0, 8.0, 9.0];
        let r = range(&data);
        for stride in [3, 4, 1 << 40, isize::MAX as usize / 8 + 1, isize::MAX as usize, usize::MAX] {
            let s = Strided::try_new(&data, stride).unwrap();
            assert_eq!((s.len(), s[0], s.get(1)), (1, 7.0, None), "stride {stride}");
            let c = s.rev().as_cview();
            assert_eq!((c.count, c.stride), (1, -8));
            assert_inside(c.data, c.count, c.stride, r);
            let mut m = [1.0, 2.0];
            let mut v = StridedMut::new(&mut m, stride);
            let c = v.as_view();
            assert_eq!((c.count, c.stride), (1, 8));
            assert!(v.set(0, 5.0) && !v.set(1, 5.0));
            assert_eq!(m, [5.0, 2.0]);
        }
        // Largest stride that still gives two elements.
        let s = Strided::new(&data, 2);
        assert_eq!((s.len(), s.as_cview().stride, s.rev().as_cview().stride), (2, 16, -16));
        let empty: [f64; 0] = [];
        let e = Strided::new(&empty, usize::MAX);
        assert_eq!((e.len(), e.as_cview().count), (0, 0));
    }

    #[test]
    fn views_stay_inside_their_slice_at_the_edges() {
        let data: Vec<f64> = (0..10).map(f64::from).collect();
        for start in [0, 1, 9, 10] {
            for stride in [1, 2, 3, 9, 10, 11, usize::MAX] {
                let s = Strided::new(&data[start..], stride);
                let r = range(&data[start..]);
                for v in [s, s.rev()] {
                    let c = v.as_cview();
                    assert_inside(c.data, c.count, c.stride, r);
                    let want: Vec<f64> = data[start..].iter().copied().step_by(stride.min(20)).collect();
                    assert_eq!(s.iter().collect::<Vec<_>>(), want, "start {start} stride {stride}");
                }
            }
        }
    }

    #[test]
    #[should_panic(expected = "index 2 out of range for a view of 2 elements")]
    fn index_past_the_end_panics() {
        let data = [1.0, 2.0, 3.0];
        let s = Strided::new(&data, 2);
        let _ = s[2];
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
        z[1] += 0.5;
        assert_eq!(xyz, [1., 10., 100., 2., 11., 101.5, 0.]);
    }

    #[test]
    fn interleaved_split_of_short_slices_points_inside() {
        for n in 0..4 {
            let mut data = vec![0.0; n];
            let r = range(&data);
            let views = StridedMut::split_interleaved::<4>(&mut data);
            for mut v in views {
                assert!(v.is_empty());
                let c = v.as_view();
                assert_inside(c.data, c.count, c.stride, r);
                assert!(!v.set(0, 1.0));
            }
        }
        // One whole point: every component has one element, at its own index.
        let mut one = [1.0, 2.0, 3.0];
        let r = range(&one);
        let [a, b, c] = StridedMut::split_interleaved::<3>(&mut one);
        assert_eq!((a[0], b[0], c[0]), (1.0, 2.0, 3.0));
        for mut v in [a, b, c] {
            let c = v.as_view();
            assert_inside(c.data, c.count, c.stride, r);
        }
        let mut single = [4.0, 5.0];
        let [s] = StridedMut::split_interleaved::<1>(&mut single);
        assert_eq!(s.as_strided().iter().collect::<Vec<_>>(), [4.0, 5.0]);
    }

    #[test]
    #[should_panic(expected = "at least one component")]
    fn interleaved_split_into_nothing_panics() {
        let mut data = [0.0; 2];
        let _ = StridedMut::split_interleaved::<0>(&mut data);
    }

    #[test]
    fn points_views_check_their_dimension() {
        let mut buf = [0.0; 10];
        let mut p = PointsMut::from(&mut buf[..]);
        let v = p.c_views(3, "pos").unwrap();
        assert_eq!((v[2].count, v[2].stride), (3, 24));
        let e = p.c_views(0, "pos").unwrap_err();
        assert_eq!((e.kind(), e.argument()), (crate::ErrorKind::Dimension, Some("pos")));
        let mut a = [0.0; 2];
        let mut b = [0.0; 2];
        let mut q = PointsMut::from([StridedMut::from(&mut a[..]), StridedMut::from(&mut b[..])]);
        assert!(q.c_views(2, "du").is_ok());
        let e = q.c_views(3, "du").unwrap_err();
        assert_eq!((e.kind(), e.argument()), (crate::ErrorKind::Dimension, Some("du")));
        assert!(e.to_string().contains("argument `du` has 2 views for points of dimension 3"), "{e}");
    }

    #[test]
    fn interleaved_points_in_short_slices_point_inside() {
        for n in 0..4 {
            let mut data = vec![0.0; n];
            let r = range(&data);
            let mut p = PointsMut::interleaved(&mut data);
            let views = p.c_views(3, "pos").unwrap();
            for v in &views[..3] {
                assert_inside(v.data, v.count, v.stride, r);
                assert_eq!(v.count, n / 3);
            }
            assert_eq!(p.capacity(3), n / 3);
        }
    }
}
