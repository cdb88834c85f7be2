//! A stable least-significant-digit radix sort of `u64` keys: `O(n)` per 8-bit digit, no
//! comparisons, the same result on every target. The mesh build sorts its edge records with it.

/// Sorts `keys` by their `DIGITS` bytes from bit `from` up (stable: keys equal there keep their
/// order), using `temp` (at least as long as `keys`; fewer than 2^32 keys) as the other buffer,
/// and returns the sorted keys (in `keys` or at the start of `temp`) and the other buffer, as
/// long as `keys`. One pass counts every digit (they do not change as the keys move); a digit on
/// which every key agrees costs no move.
pub(crate) fn sort<'a, const DIGITS: usize>(
    keys: &'a mut [u64],
    temp: &'a mut [u64],
    from: u32,
) -> (&'a mut [u64], &'a mut [u64]) {
    let n = keys.len();
    if temp.len() < n {
        return (keys, temp);
    }
    let temp = &mut temp[..n];
    let at: [u32; DIGITS] = core::array::from_fn(|d| from + 8 * d as u32);
    let digit = |k: u64, at: u32| ((k >> at) & 0xff) as usize;
    let mut count = [[0u32; 256]; DIGITS];
    for &k in keys.iter() {
        for (c, &a) in count.iter_mut().zip(&at) {
            c[digit(k, a)] += 1;
        }
    }
    let (mut src, mut dst) = (keys, temp);
    for (c, &a) in count.iter_mut().zip(&at) {
        if c.contains(&(n as u32)) {
            continue;
        }
        let mut sum = 0;
        for c in c.iter_mut() {
            (*c, sum) = (sum, sum + *c);
        }
        for &k in src.iter() {
            let slot = &mut c[digit(k, a)];
            if let Some(out) = dst.get_mut(*slot as usize) {
                *out = k;
            }
            *slot += 1;
        }
        (src, dst) = (dst, src);
    }
    (src, dst)
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
                (x % 37) << 40 | (x % 3) << 60 | i
            })
            .collect();
        let mut want = keys.clone();
        want.sort_by_key(|k| k >> 40 & 0xff_ffff); // stable
        let mut temp = vec![0; keys.len() + 3];
        let (sorted, other) = super::sort::<3>(&mut keys, &mut temp, 40);
        assert_eq!((sorted.to_vec(), other.len()), (want, 5000));
    }
}
