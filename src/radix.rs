//! A stable least-significant-digit radix sort of `u64` keys: `O(n)` per 8-bit digit, no
//! comparisons, the same result on every target. The mesh build sorts its edge records with it.

/// Most digits a sort takes: 32 bits of key.
const DIGITS: usize = 4;

/// Sorts `keys` by bits `FROM..TO` (stable: keys equal there keep their order; at most 32 bits,
/// those beyond `FROM + 32` are not looked at), using `temp` (at least as long as `keys`) as
/// the other buffer, and returns whether the sorted keys ended in `temp` (its first
/// `keys.len()` words) rather than in `keys`. Digits of 8 bits (the last one narrower where the
/// width is not a multiple of 8), counted together in one pass; a digit on which every key
/// agrees costs no move.
pub(crate) fn sort<const FROM: u32, const TO: u32>(keys: &mut [u64], temp: &mut [u64]) -> bool {
    let (from, to) = (FROM, TO);
    let n = keys.len();
    let Some(temp) = temp.get_mut(..n) else {
        return false;
    };
    let width = to.saturating_sub(from).min(8 * DIGITS as u32);
    let digits = width.div_ceil(8) as usize;
    // Digit `d`: bits `from + 8d` up to 8 of them, none at or beyond `to`.
    let digit = |k: u64, d: usize| {
        let (shift, bits) = (8 * d as u32, (width - 8 * d as u32).min(8));
        ((k >> (from + shift)) & ((1 << bits) - 1)) as usize
    };
    // Counts as u32 (n < 2^32 for every caller): 4 KB of stack however long the keys.
    let mut count = [[0u32; 256]; DIGITS];
    for &k in keys.iter() {
        for (d, c) in count.iter_mut().enumerate().take(digits) {
            c[digit(k, d)] += 1;
        }
    }
    // `in_temp`: the current order lives in `temp`.
    let mut in_temp = false;
    for (d, c) in count.iter_mut().enumerate().take(digits) {
        if c.iter().any(|&m| m as usize == n) {
            continue;
        }
        let mut at = 0;
        for m in c.iter_mut() {
            (*m, at) = (at, at + *m);
        }
        let (src, dst): (&[u64], &mut [u64]) = if in_temp {
            (&*temp, &mut *keys)
        } else {
            (&*keys, &mut *temp)
        };
        for &k in src {
            let slot = &mut c[digit(k, d)];
            if let Some(out) = dst.get_mut(*slot as usize) {
                *out = k;
            }
            *slot += 1;
        }
        in_temp = !in_temp;
    }
    in_temp
}

#[cfg(test)]
mod tests {
    #[test]
    fn sorts_like_the_standard_sort_on_the_chosen_bits() {
        // Few distinct values (stability matters, one digit moves), then two and three digits.
        for modulus in [37, 40_000, 1 << 24] {
            sort_matches::<40, 64>(modulus);
            // Bits above `to` do not count: a width that is not a multiple of 8.
            sort_matches::<40, 53>(modulus);
        }
    }

    /// Keys of `(x % modulus) << 40 | index`, sorted on bits `from..to`, against the standard
    /// stable sort on the same bits.
    fn sort_matches<const FROM: u32, const TO: u32>(modulus: u64) {
        let (from, to) = (FROM, TO);
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut keys: Vec<u64> = (0..5000)
            .map(|i| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                // The index below the sorted bits.
                (x % modulus) << 40 | i
            })
            .collect();
        let mut want = keys.clone();
        want.sort_by_key(|k| (k >> from) & ((1u64 << (to - from)) - 1)); // stable
        let mut temp = vec![0; keys.len()];
        let in_temp = super::sort::<FROM, TO>(&mut keys, &mut temp);
        assert_eq!(
            if in_temp { &temp } else { &keys },
            &want,
            "{modulus} {from}..{to}"
        );
    }
}
