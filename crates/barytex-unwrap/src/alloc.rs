//! Fallible allocation: a mesh within the limits can still ask for more memory than the
//! machine has; that is an error, not an abort.

use crate::UnwrapError;

/// An empty vector with room for `capacity` elements, or [`UnwrapError::OutOfMemory`].
pub(crate) fn try_vec_with_capacity<T>(
    capacity: usize,
    what: &'static str,
) -> Result<Vec<T>, UnwrapError> {
    let mut v = Vec::new();
    v.try_reserve_exact(capacity)
        .map_err(|_| UnwrapError::OutOfMemory {
            what,
            bytes: (capacity as u64).saturating_mul(size_of::<T>() as u64),
        })?;
    Ok(v)
}
