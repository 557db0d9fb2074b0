//! `Tracked<T>`: a value that counts the times it was lent mutably, so a
//! result computed from it can be kept until it may have changed.
//!
//! The context keeps its GL state, texture units and texture objects in
//! `Tracked`: every mutation has to go through [`Tracked::get_mut`] (reading
//! goes through `Deref`), so the compiler finds every place that can change
//! what a draw's plan is made of, and no place can forget to say so. A draw
//! whose generations are those of the last plan reuses it (the fragment key,
//! the varying layout and the uniforms: 1.2 k of the 8 k instructions a
//! `glBegin`/`glEnd` quad cost, callgrind over `osmesa/bench/quads.c`).

use std::ops::Deref;

/// A value and the number of mutable borrows it has lent.
#[derive(Clone, Debug, Default)]
pub struct Tracked<T> {
    value: T,
    generation: u64,
}

impl<T> Tracked<T> {
    pub fn new(value: T) -> Tracked<T> {
        Tracked { value, generation: 0 }
    }

    /// The value, to change: the generation moves on whether or not it does.
    pub fn get_mut(&mut self) -> &mut T {
        self.generation = self.generation.wrapping_add(1);
        &mut self.value
    }

    /// Changes with every [`Tracked::get_mut`].
    pub fn generation(&self) -> u64 {
        self.generation
    }
}

impl<T> Deref for Tracked<T> {
    type Target = T;

    fn deref(&self) -> &T {
        &self.value
    }
}

#[cfg(test)]
mod tests {
    use super::Tracked;

    #[test]
    fn each_mutable_borrow_moves_the_generation() {
        let mut t = Tracked::new(5);
        assert_eq!((*t, t.generation()), (5, 0));
        let _ = *t + 1;
        assert_eq!(t.generation(), 0);
        *t.get_mut() = 6;
        let _ = t.get_mut();
        assert_eq!((*t, t.generation()), (6, 2));
    }
}
