//! The triangle queue between the command parser and cull & sort in `gpu_top`, cycle by
//! cycle; `rtl::triangle_queue` mirrors it on every cycle.
//!
//! A mesh's back faces come in runs that cull & sort drops in a cycle each, faster than
//! the command parser (001, Fig. 4) reads triangles; its front faces keep setup and the
//! span unit busy for tens of cycles each. The queue lets the parser run ahead during the
//! latter and feeds the rasterizer from what it banked during the former (on the knot,
//! 2,400 triangles: 15% more cycles than `raster_top` fed directly without it, 3.5% with
//! 512 entries).
//!
//! **Timing.** A triangle is taken while fewer than `depth` are queued (the count as the
//! cycle began: one taken out in the same cycle does not make room); it is at the head
//! from the second cycle after it was taken (block RAM: its write and its read never share
//! a clock edge), and leaves the cycle it is taken from the head.

use crate::input::Vtx;
use std::collections::VecDeque;

/// A triangle as the queue holds it: its vertices (TI's end flags stay with the parser).
pub type Triangle = [Vtx; 3];

/// What the queue drives, one cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    /// A triangle offered is taken (fewer than `depth` queued).
    pub in_ready: bool,
    /// The head, once readable.
    pub out: Option<Triangle>,
    /// Nothing queued.
    pub idle: bool,
}

/// The queue's state: see the module documentation.
#[derive(Clone, Debug)]
pub struct TriangleQueue {
    depth: usize,
    entries: VecDeque<Triangle>,
    /// A triangle was taken in the last cycle (the newest entry, not yet readable).
    fresh: bool,
}

impl TriangleQueue {
    /// An empty queue of `depth` entries, a power of two from 4 to 512.
    pub fn new(depth: usize) -> Result<TriangleQueue, String> {
        if !(depth.is_power_of_two() && (4..=512).contains(&depth)) {
            return Err(format!("a triangle queue of {depth} entries: a power of two from 4 to 512"));
        }
        Ok(TriangleQueue { depth, entries: VecDeque::with_capacity(depth), fresh: false })
    }

    /// What the queue drives this cycle.
    pub fn outputs(&self) -> Outputs {
        let readable = self.entries.len() - usize::from(self.fresh);
        Outputs {
            in_ready: self.entries.len() < self.depth,
            out: self.entries.front().copied().filter(|_| readable > 0),
            idle: self.entries.is_empty(),
        }
    }

    /// The clock edge: `inp` offered, the head taken if `out_ready`.
    pub fn clock(&mut self, inp: Option<Triangle>, out_ready: bool) {
        let o = self.outputs();
        if o.out.is_some() && out_ready {
            self.entries.pop_front();
        }
        self.fresh = false;
        if let (Some(t), true) = (inp, o.in_ready) {
            self.entries.push_back(t);
            self.fresh = true;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri(k: i128) -> Triangle {
        [Vtx { x: k, y: 0, z: 0, c: [0; 3], iw: 0 }; 3]
    }

    /// Derived by hand: a triangle taken in cycle 0 is at the head in cycle 2; with the
    /// head never taken, four fill a queue of four and the fifth waits.
    #[test]
    fn a_triangle_shows_two_cycles_after_it_is_taken_and_four_fill_four() {
        let mut q = TriangleQueue::new(4).unwrap();
        assert_eq!(q.outputs(), Outputs { in_ready: true, out: None, idle: true });
        q.clock(Some(tri(0)), true);
        assert_eq!(q.outputs(), Outputs { in_ready: true, out: None, idle: false });
        q.clock(Some(tri(1)), false);
        assert_eq!(q.outputs().out, Some(tri(0)));
        q.clock(Some(tri(2)), false);
        q.clock(Some(tri(3)), false);
        assert!(!q.outputs().in_ready);
        // Taking the head does not make room in the same cycle: the fifth is refused.
        q.clock(Some(tri(4)), true);
        assert_eq!(q.outputs().out, Some(tri(1)));
        assert!(q.outputs().in_ready);
        for k in 1..4 {
            assert_eq!(q.outputs().out, Some(tri(k)));
            q.clock(None, true);
        }
        assert_eq!(q.outputs(), Outputs { in_ready: true, out: None, idle: true });
    }

    #[test]
    fn sizes_outside_4_to_512_or_not_powers_of_two_are_refused() {
        for d in [0, 2, 3, 48, 1024] {
            assert!(TriangleQueue::new(d).is_err(), "{d}");
        }
    }
}
