//! A bit for each triangle or vertex, in words of 64: which the kept visibility shows, so
//! that a frame that only lights again does no work for the others.

/// Is bit `i` of `mask` set? (A bit past the end is not.)
#[inline(always)]
pub fn is_set(mask: &[u64], i: usize) -> bool {
    mask.get(i / 64).is_some_and(|w| w >> (i % 64) & 1 == 1)
}

/// Sets bit `i` of `mask` (nothing for a bit past the end).
#[inline(always)]
pub fn set(mask: &mut [u64], i: usize) {
    if let Some(w) = mask.get_mut(i / 64) {
        *w |= 1 << (i % 64);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bits_are_set_and_read_where_asked_and_not_past_the_end() {
        let mut m = vec![0u64; 2];
        for i in [0, 63, 64, 127, 128, 500] {
            set(&mut m, i);
        }
        assert_eq!(m, [1 | 1 << 63, 1 | 1 << 63]);
        let set_bits: Vec<usize> = (0..200).filter(|i| is_set(&m, *i)).collect();
        assert_eq!(set_bits, [0, 63, 64, 127]);
    }
}
