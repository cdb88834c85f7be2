//! A stable least-significant-digit radix sort of `u64` keys: `O(n)` per 8-bit digit, no
//! comparisons, the same result on every target. The mesh build sorts its edge records with it.

/// Sorts `keys` by bits `from..to` (stable: keys equal there keep their order), using `temp`
/// (at least as long as `keys`) as the other buffer. Digits of 8 bits; a digit on which every key
/// agrees costs one counting pass and no move.
pub(crate) fn sort(keys: &mut [u64], temp: &mut [u64], from: u32, to: u32) {
    let n = keys.len();
    let Some(temp) = temp.get_mut(..n) else {
        return;
    };
    // `in_temp`: the current order lives in `temp`.
    let mut in_temp = false;
    let mut shift = from;
    while shift < to {
        let width = (to - shift).min(8);
        let mask = (1u64 << width) - 1;
        let (src, dst): (&[u64], &mut [u64]) = if in_temp {
            (&*temp, &mut *keys)
        } else {
            (&*keys, &mut *temp)
        };
        let mut count = [0usize; 256];
        for &k in src {
            count[((k >> shift) & mask) as usize] += 1;
        }
        if count.contains(&n) {
            shift += width;
            continue;
        }
        let mut at = 0;
        for c in count.iter_mut() {
            (*c, at) = (at, at + *c);
        }
        for &k in src {
            let d = ((k >> shift) & mask) as usize;
            dst[count[d]] = k;
            count[d] += 1;
        }
        in_temp = !in_temp;
        shift += width;
    }
    if in_temp {
        keys.copy_from_slice(temp);
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn sorts_like_the_standard_sort_on_the_chosen_bits() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut keys: Vec<u64> = (0..5000)
            .map(|i| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                // Few distinct high parts, so stability matters; the index below.
                (x % 37) << 40 | i
            })
            .collect();
        let mut want = keys.clone();
        want.sort_by_key(|k| k >> 40); // stable
        let mut temp = vec![0; keys.len()];
        super::sort(&mut keys, &mut temp, 40, 64);
        assert_eq!(keys, want);
    }
}
