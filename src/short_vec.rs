//! [`ShortVec`]: an island's z, w and contact indices, held inline up to
//! [`SHORT_INLINE`] entries and on the heap beyond.
//!
//! Why: a batch of small LCPs used to own three heap vectors per island
//! (`contacts`, z and w). At n = 4 the default CPU path spent ~14 % of its
//! time and ~20 % of its instructions in the allocator: freeing one batch's
//! thousands of small blocks and allocating the next batch's sent glibc
//! down its slow path (BENCHMARKS.md, issue 11). Contact islands and the
//! benchmarks' problems are mostly this small, so they now allocate nothing.
//!
//! It reads as a slice (`Deref<Target = [T]>`): indexing, `iter()`, `len()`,
//! `to_vec()`, and `&v` where a `&[T]` is wanted. It compares equal to a
//! `Vec`, slice or array with the same entries, and serialises as a
//! sequence, exactly as the `Vec` it replaces.

use std::fmt;
use std::ops::{Deref, DerefMut};

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// Entries a [`ShortVec`] holds without allocating: islands up to n = 8
/// (the sizes of issue 11's small-batch targets, n = 4 and 8).
pub const SHORT_INLINE: usize = 8;

/// A vector of up to [`SHORT_INLINE`] entries inline, more on the heap; see
/// the module docs.
///
/// ```
/// use lcpbatch::ShortVec;
///
/// let z: ShortVec<f64> = vec![1.0, 2.0].into();
/// assert_eq!(z, vec![1.0, 2.0]);
/// assert_eq!(z[1], 2.0);
/// assert_eq!(z.iter().sum::<f64>(), 3.0);
/// let owned: Vec<f64> = z.into_vec();
/// assert_eq!(owned, [1.0, 2.0]);
/// ```
#[derive(Clone)]
pub struct ShortVec<T: Copy + Default> {
    /// Entries held: `items[..len]` while len ≤ [`SHORT_INLINE`], else all
    /// of `heap`.
    len: usize,
    /// The entries while they fit.
    items: [T; SHORT_INLINE],
    /// The entries once they do not (empty, unallocated, before).
    // A plain struct, not an enum of the two: every field stays aligned,
    // so that building one and moving it into a report costs whole-word
    // copies (an enum packed its length next to the tag, and the moves'
    // wide loads stalled on the narrow stores before them).
    heap: Vec<T>,
}

impl<T: Copy + Default> ShortVec<T> {
    /// An empty vector (nothing allocated).
    pub fn new() -> Self {
        ShortVec {
            len: 0,
            items: [T::default(); SHORT_INLINE],
            heap: Vec::new(),
        }
    }

    /// `n` copies of `value` (allocates only for n > [`SHORT_INLINE`]).
    pub fn from_elem(value: T, n: usize) -> Self {
        ShortVec {
            len: n,
            items: [value; SHORT_INLINE],
            heap: if n > SHORT_INLINE {
                vec![value; n]
            } else {
                Vec::new()
            },
        }
    }

    /// Makes it `n` copies of `value` in place, keeping any heap block
    /// (allocates only for n > [`SHORT_INLINE`] and a block too small).
    pub fn reset(&mut self, value: T, n: usize) {
        self.heap.clear();
        if n > SHORT_INLINE {
            self.heap.resize(n, value);
        } else {
            self.items = [value; SHORT_INLINE];
        }
        self.len = n;
    }

    /// The entries as a slice.
    #[inline]
    pub fn as_slice(&self) -> &[T] {
        if self.len <= SHORT_INLINE {
            &self.items[..self.len]
        } else {
            &self.heap
        }
    }

    /// The entries as a mutable slice.
    #[inline]
    pub fn as_mut_slice(&mut self) -> &mut [T] {
        if self.len <= SHORT_INLINE {
            &mut self.items[..self.len]
        } else {
            &mut self.heap
        }
    }

    /// Appends `value`, moving the entries to the heap when the inline
    /// space is full.
    pub fn push(&mut self, value: T) {
        if self.len < SHORT_INLINE {
            self.items[self.len] = value;
        } else {
            if self.len == SHORT_INLINE {
                self.heap.reserve(2 * SHORT_INLINE);
                self.heap.extend_from_slice(&self.items);
            }
            self.heap.push(value);
        }
        self.len += 1;
    }

    /// The entries as a `Vec` (reusing the heap block when there is one).
    pub fn into_vec(self) -> Vec<T> {
        if self.len <= SHORT_INLINE {
            self.items[..self.len].to_vec()
        } else {
            self.heap
        }
    }

    /// Whether the entries live on the heap (more than [`SHORT_INLINE`]).
    pub fn spilled(&self) -> bool {
        self.len > SHORT_INLINE
    }
}

impl ShortVec<usize> {
    /// 0, 1, …, n − 1: an LCP batch's contact list, copied whole from a
    /// constant while it fits (no per-entry stores for the report's move
    /// of it to stall on).
    pub(crate) fn indices(n: usize) -> Self {
        const FIRST: [usize; SHORT_INLINE] = {
            let mut a = [0; SHORT_INLINE];
            let mut i = 0;
            while i < SHORT_INLINE {
                a[i] = i;
                i += 1;
            }
            a
        };
        if n > SHORT_INLINE {
            return (0..n).collect();
        }
        ShortVec {
            len: n,
            items: FIRST,
            heap: Vec::new(),
        }
    }
}

impl<T: Copy + Default> Default for ShortVec<T> {
    fn default() -> Self {
        ShortVec::new()
    }
}

impl<T: Copy + Default> Deref for ShortVec<T> {
    type Target = [T];
    #[inline]
    fn deref(&self) -> &[T] {
        self.as_slice()
    }
}

impl<T: Copy + Default> DerefMut for ShortVec<T> {
    #[inline]
    fn deref_mut(&mut self) -> &mut [T] {
        self.as_mut_slice()
    }
}

impl<T: Copy + Default> AsRef<[T]> for ShortVec<T> {
    fn as_ref(&self) -> &[T] {
        self
    }
}

impl<T: Copy + Default> std::borrow::Borrow<[T]> for ShortVec<T> {
    fn borrow(&self) -> &[T] {
        self
    }
}

impl<T: Copy + Default> From<&[T]> for ShortVec<T> {
    fn from(s: &[T]) -> Self {
        if s.len() > SHORT_INLINE {
            return ShortVec::from(s.to_vec());
        }
        let mut items = [T::default(); SHORT_INLINE];
        items[..s.len()].copy_from_slice(s);
        ShortVec {
            len: s.len(),
            items,
            heap: Vec::new(),
        }
    }
}

impl<T: Copy + Default, const K: usize> From<[T; K]> for ShortVec<T> {
    fn from(a: [T; K]) -> Self {
        ShortVec::from(&a[..])
    }
}

impl<T: Copy + Default> From<Vec<T>> for ShortVec<T> {
    /// Short vectors are copied inline (and the block freed); longer ones
    /// keep their heap block.
    fn from(v: Vec<T>) -> Self {
        if v.len() <= SHORT_INLINE {
            return ShortVec::from(v.as_slice());
        }
        ShortVec {
            len: v.len(),
            items: [T::default(); SHORT_INLINE],
            heap: v,
        }
    }
}

impl<T: Copy + Default> From<ShortVec<T>> for Vec<T> {
    fn from(v: ShortVec<T>) -> Self {
        v.into_vec()
    }
}

impl<T: Copy + Default> FromIterator<T> for ShortVec<T> {
    /// Fills the inline space first with no per-entry check of where the
    /// entries live (`(0..n).collect()` builds every island's contact list).
    fn from_iter<I: IntoIterator<Item = T>>(iter: I) -> Self {
        let mut iter = iter.into_iter();
        let mut v = ShortVec::new();
        for slot in v.items.iter_mut() {
            match iter.next() {
                Some(x) => *slot = x,
                None => return v,
            }
            v.len += 1;
        }
        v.extend(iter);
        v
    }
}

impl<T: Copy + Default> Extend<T> for ShortVec<T> {
    fn extend<I: IntoIterator<Item = T>>(&mut self, iter: I) {
        for x in iter {
            self.push(x);
        }
    }
}

impl<'a, T: Copy + Default> IntoIterator for &'a ShortVec<T> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<'a, T: Copy + Default> IntoIterator for &'a mut ShortVec<T> {
    type Item = &'a mut T;
    type IntoIter = std::slice::IterMut<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter_mut()
    }
}

impl<T: Copy + Default> IntoIterator for ShortVec<T> {
    type Item = T;
    type IntoIter = IntoIter<T>;
    fn into_iter(self) -> IntoIter<T> {
        IntoIter { v: self, next: 0 }
    }
}

/// The entries of a [`ShortVec`] by value, in order.
#[derive(Clone, Debug)]
pub struct IntoIter<T: Copy + Default> {
    v: ShortVec<T>,
    next: usize,
}

impl<T: Copy + Default> Iterator for IntoIter<T> {
    type Item = T;
    fn next(&mut self) -> Option<T> {
        let x = self.v.get(self.next).copied();
        self.next += usize::from(x.is_some());
        x
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.v.len() - self.next;
        (left, Some(left))
    }
}

impl<T: Copy + Default> ExactSizeIterator for IntoIter<T> {}

impl<T: Copy + Default + fmt::Debug> fmt::Debug for ShortVec<T> {
    /// As a list, like the `Vec` it replaces.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl<T: Copy + Default + PartialEq> PartialEq for ShortVec<T> {
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl<T: Copy + Default + Eq> Eq for ShortVec<T> {}

impl<T: Copy + Default + std::hash::Hash> std::hash::Hash for ShortVec<T> {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.as_slice().hash(state)
    }
}

impl<T: Copy + Default + PartialEq> PartialEq<Vec<T>> for ShortVec<T> {
    fn eq(&self, other: &Vec<T>) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl<T: Copy + Default + PartialEq> PartialEq<ShortVec<T>> for Vec<T> {
    fn eq(&self, other: &ShortVec<T>) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl<T: Copy + Default + PartialEq> PartialEq<[T]> for ShortVec<T> {
    fn eq(&self, other: &[T]) -> bool {
        self.as_slice() == other
    }
}

impl<T: Copy + Default + PartialEq> PartialEq<&[T]> for ShortVec<T> {
    fn eq(&self, other: &&[T]) -> bool {
        self.as_slice() == *other
    }
}

impl<T: Copy + Default + PartialEq, const K: usize> PartialEq<[T; K]> for ShortVec<T> {
    fn eq(&self, other: &[T; K]) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl<T: Copy + Default + Serialize> Serialize for ShortVec<T> {
    /// A sequence, as a `Vec` serialises.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.as_slice().serialize(s)
    }
}

impl<'de, T: Copy + Default + Deserialize<'de>> Deserialize<'de> for ShortVec<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Vec::<T>::deserialize(d).map(ShortVec::from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_and_long_vectors_read_and_compare_as_their_entries() {
        for n in [0, 1, SHORT_INLINE, SHORT_INLINE + 1, 3 * SHORT_INLINE] {
            let entries: Vec<usize> = (0..n).collect();
            let v: ShortVec<usize> = (0..n).collect();
            assert_eq!(v, entries);
            assert_eq!(v.spilled(), n > SHORT_INLINE, "n = {n}");
            assert_eq!(ShortVec::from(entries.clone()), v);
            assert_eq!(ShortVec::from(entries.as_slice()), v);
            assert_eq!(v.clone().into_iter().collect::<Vec<_>>(), entries);
            assert_eq!(v.iter().copied().collect::<Vec<_>>(), entries);
            assert_eq!(v.clone().into_vec(), entries);
            assert_eq!(format!("{v:?}"), format!("{entries:?}"));
            assert_eq!(ShortVec::from_elem(7usize, n), vec![7; n]);
        }
    }

    #[test]
    fn it_serialises_as_the_vec_it_replaces() {
        for n in [0, 3, SHORT_INLINE + 2] {
            // Halves: exact in decimal, so the JSON text reads back to the same bits.
            let entries: Vec<f64> = (0..n).map(|i| i as f64 * 0.5 - 1.25).collect();
            let v = ShortVec::from(entries.clone());
            let json = serde_json::to_string(&v).unwrap();
            assert_eq!(json, serde_json::to_string(&entries).unwrap());
            let back: ShortVec<f64> = serde_json::from_str(&json).unwrap();
            assert_eq!(back, v);
        }
    }

    #[test]
    fn writes_through_the_slice_are_kept() {
        let mut v = ShortVec::from_elem(0.0f64, 4);
        v[2] = 5.0;
        for x in &mut v {
            *x += 1.0;
        }
        assert_eq!(v, [1.0, 1.0, 6.0, 1.0]);
    }
}
