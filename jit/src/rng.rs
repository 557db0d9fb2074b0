//! The one deterministic generator of softgl's tests, benches, conformance
//! scenes and demo: Marsaglia's xorshift32 (shifts 13, 17, 5), period
//! 2^32 - 1. The same numbers on every machine and run, so a failure replays;
//! not for anything that must be unpredictable.

/// A xorshift32 generator.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rng(u32);

impl Rng {
    /// A generator seeded with `seed` (0, a state xorshift never leaves, reads as 1).
    pub fn new(seed: u32) -> Rng {
        Rng(seed.max(1))
    }

    /// The next 32 bits (the state after one step).
    pub fn next_u32(&mut self) -> u32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        self.0
    }

    /// 64 bits from two steps, the first in the high half.
    pub fn next_u64(&mut self) -> u64 {
        let hi = u64::from(self.next_u32());
        (hi << 32) | u64::from(self.next_u32())
    }

    /// A number in `0..n` (by remainder; `n > 0`).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }

    /// A float in `[0, 1)` from the high 24 bits of one step.
    pub fn unit(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 / (1u32 << 24) as f32
    }

    /// A float in `[a, b)`.
    pub fn range(&mut self, a: f32, b: f32) -> f32 {
        a + (b - a) * self.unit()
    }

    /// One of `v`'s elements (`v` not empty).
    pub fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.below(v.len() as u64) as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::Rng;

    #[test]
    fn the_sequence_is_marsaglias_xorshift32() {
        // Marsaglia (2003), "Xorshift RNGs": from 2463534242 the first output is 723471715.
        let mut r = Rng::new(2_463_534_242);
        assert_eq!(r.next_u32(), 723_471_715);
        let mut zero = Rng::new(0);
        assert_eq!(zero.next_u32(), Rng::new(1).next_u32(), "seed 0 reads as 1");
        let mut a = Rng::new(7);
        let (x, y) = (a.clone().next_u32(), a.clone().next_u32());
        assert_eq!(a.next_u64(), (u64::from(x) << 32) | u64::from(Rng::new(x).next_u32()));
        assert_eq!(x, y);
        for _ in 0..1000 {
            let u = a.unit();
            assert!((0.0..1.0).contains(&u), "{u}");
            assert!(a.below(10) < 10);
        }
    }
}
