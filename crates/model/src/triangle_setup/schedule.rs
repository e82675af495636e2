//! The schedule `rtl::triangle_setup` runs: when each of setup's 64 products, its
//! normalise, its seven divisions and its hand-over happen, in cycles after the cycle that
//! takes the triangle (001 §II.2.라, Table 3: one shared divider, reused multipliers).
//!
//! A modulo schedule: setup takes a new triangle every II cycles, so triangles II
//! cycles apart overlap, and each multiplier lane and the divider are reserved per cycle
//! modulo II (no two triangles on the grid ever want the same one in the same cycle).
//! Products are placed by a list scheduler in the order of the data flow, each in the
//! first cycle from which its operands are ready (or a few cycles later, see `Placement`)
//! with a lane free; II is the lowest at which every product fits and every register the
//! triangles share lives at most II cycles.
//!
//! A multiplier is a pipeline of [`MULTIPLIER_STAGES`] registers (operands, partial
//! products, product: `rtl::mul::SplitMul`): a product placed in cycle c has its operands
//! selected in c and is added into its destination in c + 3, readable from c + 4. Triangles are taken on the II grid only
//! (or at once when setup is empty): `model::cycles::scanline_frame` follows that rule.
//!
//! The registers of a triangle that live longer than II (its vertices, crossings, the area's
//! sign and exponent, each edge's start and step: x, r, q, rho) are copied every II cycles,
//! [`Schedule::copies`] of them: cycle c reads copy [`Schedule::view`]`(c)`. Every other
//! register (the area, the normalised area, the numerators, 1/area shifted, eq. (2)'s
//! products, the gradients, the starts and increments) is shared, and [`Schedule::new`]
//! checks that the next triangle writes it only after this one has read it for the last time.

/// Products in setup: twice the area 2, edge numerators 6, eq. (2) 4, gradients 16, starts
/// and increments 36. Product i: area 0, 1; numerators 2 + 2e (dy * x fraction) and 3 + 2e
/// (dx * t) of edge e; eq. (2) 8 + d; gradients 12 + 4a + j of attribute a (j 0, 1 into
/// ddx, 2, 3 into ddy); starts 28 + 12e + 3a + j (j 0: ddx * off_x, 1: ddy * off_y, into
/// the start; 2: ddx * q, the increment).
pub const PRODUCTS: usize = 64;

/// Most multipliers setup can use: with more, II would still be bound by the divider's
/// seven divisions and the registers' lifetimes.
pub const MULTIPLIERS_MAX: usize = 7;

/// Registers in a multiplier: its operands, its partial products (one per DSP block) and
/// their sum, the product.
pub const MULTIPLIER_STAGES: usize = 3;

/// Cycles from a division's issue into the divider: its operands are registered, so that
/// no path runs from the geometry into the divider's first stage.
pub const DIVIDER_OPERANDS: usize = 1;

/// Most copies of a triangle's registers: II is at least a sixth of the latency.
pub const COPIES_MAX: usize = 6;

const M: usize = MULTIPLIER_STAGES;

/// Most cycles the list scheduler holds back the gradients, or the first starts, beyond
/// their operands' readiness ([`Placement`]).
const DELAY_MAX: usize = 8;

/// How the list scheduler places the gradients and the starts. Placed as soon as their
/// operands are ready, the gradients of the last attribute wait for its starts and the
/// first starts for the last ones, and those registers can live longer than II; held back
/// or reordered, the same products pack into fewer cycles. [`Schedule::new`] tries every
/// placement and keeps the one with the lowest latency at the lowest II.
#[derive(Clone, Copy, Debug)]
struct Placement {
    /// Cycles the gradients wait beyond eq. (2)'s products.
    gradient_delay: usize,
    /// No start or increment is placed before the first one is ready plus this.
    start_delay: usize,
    /// Among starts ready in the same cycle, the last attribute's first.
    last_attribute_first: bool,
}

impl Placement {
    fn all() -> impl Iterator<Item = Placement> + Clone {
        (0..=DELAY_MAX).flat_map(|gradient_delay| {
            (0..=DELAY_MAX).flat_map(move |start_delay| {
                [false, true].map(|last_attribute_first| Placement {
                    gradient_delay,
                    start_delay,
                    last_attribute_first,
                })
            })
        })
    }
}

/// When each step of setup happens, in cycles after the cycle that takes the triangle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Schedule {
    pub multipliers: usize,
    pub divider_latency: usize,
    /// Per product: the cycle its operands are selected in, and its multiplier. It is
    /// added into its destination in cycle + [`MULTIPLIER_STAGES`] ([`Schedule::add`]).
    pub slots: Vec<(usize, usize)>,
    /// The cycle twice the area is normalised into a register (1/area is issued later).
    pub normalise: usize,
    /// The seven divisions' issue cycles, in the model's order (1/area, then per edge the
    /// start and the step); all in copy 0 (at most II).
    pub issue: [usize; 7],
    /// The hand-over cycle (each start becomes v0's attribute plus the plane's value); the
    /// result is valid from the next one.
    pub handover: usize,
    pub latency: usize,
    /// II: setup takes triangles `interval` cycles apart (or when it is empty).
    pub interval: usize,
    /// Copies of a triangle's long-lived registers, ceil(latency / II).
    pub copies: usize,
}

/// A shared register's life in a triangle's schedule: the cycles that write it (at their
/// end) and the last one that reads it. It fits II when the next triangle, II cycles
/// later, writes it first after this one's last read and after this one's last write.
struct Life {
    writes: Vec<usize>,
    last_read: usize,
}

impl Schedule {
    /// The schedule for `k` multipliers (1 to [`MULTIPLIERS_MAX`]) and an `l`-stage divider
    /// (1 or more): the lowest II at which it fits, then the latency the list scheduler finds.
    pub fn new(k: usize, l: usize) -> Result<Schedule, String> {
        if !(1..=MULTIPLIERS_MAX).contains(&k) {
            return Err(format!("triangle_setup: K = {k} multipliers is not supported: 1 to {MULTIPLIERS_MAX}"));
        }
        if l == 0 {
            return Err("triangle_setup: the divider needs 1 stage or more, not 0".into());
        }
        // Each lane holds II products of a triangle, the divider 7 divisions.
        let lowest = PRODUCTS.div_ceil(k).max(7);
        (lowest..=4 * (PRODUCTS + l))
            .find_map(|ii| {
                Placement::all().filter_map(|p| Schedule::at_interval(k, l, ii, p)).min_by_key(|s| s.latency)
            })
            .ok_or_else(|| format!("triangle_setup: no schedule for K = {k}, L = {l}"))
    }

    /// The list schedule at II = `ii` and placement `p`, if its lanes, divisions, copies
    /// and shared registers' lives fit.
    fn at_interval(k: usize, l: usize, ii: usize, p: Placement) -> Option<Schedule> {
        let mut lanes = vec![vec![false; ii]; k];
        let mut divider = vec![false; ii];
        let mut slots = vec![(0, 0); PRODUCTS];
        // The first cycle from `ready` with a lane free (modulo II).
        let mut place = |i: usize, ready: usize| -> Option<usize> {
            let (c, lane) = (ready..ready + ii).find_map(|c| (0..k).find(|&m| !lanes[m][c % ii]).map(|m| (c, m)))?;
            lanes[lane][c % ii] = true;
            slots[i] = (c, lane);
            Some(c)
        };
        let mut issue_at = |ready: usize| -> Option<usize> {
            let c = (ready..ready + ii).find(|&c| !divider[c % ii])?;
            divider[c % ii] = true;
            Some(c)
        };
        // A product's result is readable M + 1 cycles after its slot.
        let ready_after = |c: usize| c + M + 1;
        // Twice the area, normalised once summed, then 1/area issued: the longest path.
        let area = [place(0, 1)?, place(1, 1)?];
        let normalise = ready_after(area[0].max(area[1]));
        let mut issue = [0; 7];
        issue[0] = issue_at(normalise + 1)?;
        // The numerators; each edge's start division once its two are summed, its step
        // (from the vertices alone) in any free cycle.
        let mut numerators = [0; 6];
        for (n, c) in numerators.iter_mut().enumerate() {
            *c = place(2 + n, 1)?;
        }
        for e in 0..3 {
            issue[1 + 2 * e] = issue_at(ready_after(numerators[2 * e].max(numerators[2 * e + 1])))?;
            issue[2 + 2 * e] = issue_at(1)?;
        }
        if issue.iter().any(|&c| c > ii) {
            return None;
        }
        let result = |j: usize| issue[j] + DIVIDER_OPERANDS + l;
        // eq. (2) from the cycle after 1/area is back (shifted into a register), the
        // gradients once all four of its products are in.
        let eq2: Vec<usize> = (0..4).map(|d| place(8 + d, result(0) + 1)).collect::<Option<_>>()?;
        let eq2_ready = ready_after(*eq2.iter().max()?);
        let gradients: Vec<usize> = (12..28).map(|i| place(i, eq2_ready + p.gradient_delay)).collect::<Option<_>>()?;
        let grad_ready = |a: usize| ready_after(*gradients[4 * a..4 * a + 4].iter().max().unwrap());
        // Starts and increments, in the order they are ready: the start's two products
        // (which share an accumulator) together, the increment once its step is back.
        let mut starts: Vec<(usize, usize)> = Vec::with_capacity(36);
        for e in 0..3 {
            for a in 0..4 {
                let (i, g) = (28 + 12 * e + 3 * a, grad_ready(a));
                let start = g.max(result(1 + 2 * e) + 1);
                starts.extend([(start, i), (start, i + 1), (g.max(result(2 + 2 * e) + 1), i + 2)]);
            }
        }
        // Product 28 + 12e + 3a + j: attribute a.
        let attribute = |i: usize| (i - 28) % 12 / 3;
        starts.sort_by_key(|&(ready, i)| (ready, if p.last_attribute_first { 3 - attribute(i) } else { 0 }));
        let first = starts[0].0 + p.start_delay;
        for &(ready, i) in &starts {
            place(i, ready.max(first))?;
        }
        let add = |i: usize| slots[i].0 + M;
        let handover = (28..PRODUCTS).map(add).max()?.max((0..7).map(result).max()?) + 1;
        let latency = handover + 1;
        let copies = latency.div_ceil(ii);
        if copies > COPIES_MAX {
            return None;
        }
        // The shared registers' lives: the next triangle writes each II cycles after this one.
        let slot = |i: usize| slots[i].0;
        let mut lives = vec![
            // The area (its sign is copied at II), the normalised area, 1/area shifted
            // and the area's exponent (read where eq. (2)'s products are added).
            Life { writes: vec![add(0), add(1)], last_read: ii },
            Life { writes: vec![normalise], last_read: issue[0] },
            Life { writes: vec![result(0)], last_read: (8..12).map(add).max()? },
        ];
        for e in 0..3 {
            // Edge e's numerator, read by its start division.
            lives.push(Life { writes: vec![add(2 + 2 * e), add(3 + 2 * e)], last_read: issue[1 + 2 * e] });
        }
        for d in 0..4 {
            // eq. (2)'s products, read by the gradients.
            lives.push(Life { writes: vec![add(8 + d)], last_read: (12..28).map(slot).max()? });
        }
        for a in 0..4 {
            let of = |j: usize| (0..3).map(move |e| 28 + 12 * e + 3 * a + j);
            // ddx: read by the x and q products and, where each increment is added, into
            // inc1 and the ddx output register; ddy: by the y products and into inc0.
            let ddx_read = of(0).chain(of(2)).map(slot).chain(of(2).map(add)).max()?;
            let ddy_read = of(1).map(slot).chain(of(2).map(add)).max()?;
            lives.push(Life { writes: vec![add(12 + 4 * a), add(13 + 4 * a)], last_read: ddx_read });
            lives.push(Life { writes: vec![add(14 + 4 * a), add(15 + 4 * a)], last_read: ddy_read });
            // The ddx output, written with each increment, then held to the result;
            // each start (v0's attribute added at the hand-over) and increments.
            lives.push(Life { writes: of(2).map(add).collect(), last_read: latency });
            for e in 0..3 {
                let i = 28 + 12 * e + 3 * a;
                lives.push(Life { writes: vec![add(i), add(i + 1), handover], last_read: latency });
                lives.push(Life { writes: vec![add(i + 2)], last_read: latency });
            }
        }
        let fits = |life: &Life| {
            let (first, last) = (*life.writes.iter().min().unwrap(), *life.writes.iter().max().unwrap());
            life.last_read - first <= ii && last - first < ii
        };
        if !lives.iter().all(fits) {
            return None;
        }
        Some(Schedule {
            multipliers: k,
            divider_latency: l,
            slots,
            normalise,
            issue,
            handover,
            latency,
            interval: ii,
            copies,
        })
    }

    /// The cycle product `i` is added into its destination (its product register's output).
    pub fn add(&self, i: usize) -> usize {
        self.slots[i].0 + M
    }

    /// The cycle a division's result is at the divider's output.
    pub fn result(&self, division: usize) -> usize {
        self.issue[division] + DIVIDER_OPERANDS + self.divider_latency
    }

    /// The copy of the triangle's registers cycle `c` (1 to the latency) reads.
    pub fn view(&self, c: usize) -> usize {
        (c - 1) / self.interval
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every schedule keeps the data flow (a product only after what it reads is in its
    /// register) and reserves each lane and the divider once per cycle modulo II.
    #[test]
    fn schedule_keeps_the_data_flow_and_its_reservations() {
        for k in 1..=MULTIPLIERS_MAX {
            for l in 1..=40 {
                let s = Schedule::new(k, l).unwrap();
                let (ii, cyc, ready) = (s.interval, |i: usize| s.slots[i].0, |i: usize| s.add(i) + 1);
                let mut lanes = std::collections::HashSet::new();
                assert!(s.slots.iter().all(|&(c, m)| c >= 1 && m < k && lanes.insert((c % ii, m))), "K {k} L {l}");
                let mut divider = std::collections::HashSet::new();
                assert!(s.issue.iter().all(|&c| c <= ii && divider.insert(c % ii)), "K {k} L {l}: {s:?}");
                // Area -> normalise -> 1/area -> eq. (2) -> gradients -> starts -> hand-over.
                assert!(s.normalise >= ready(0).max(ready(1)) && s.issue[0] > s.normalise);
                assert!((8..12).all(|i| cyc(i) > s.result(0)));
                assert!((12..28).all(|g| (8..12).all(|e| cyc(g) >= ready(e))));
                for e in 0..3 {
                    assert!(s.issue[1 + 2 * e] >= ready(2 + 2 * e).max(ready(3 + 2 * e)));
                    for a in 0..4 {
                        let i = 28 + 12 * e + 3 * a;
                        let grads = (12 + 4 * a..16 + 4 * a).map(ready).max().unwrap();
                        assert!(cyc(i).min(cyc(i + 1)).min(cyc(i + 2)) >= grads, "K {k} L {l}");
                        assert!(cyc(i) > s.result(1 + 2 * e) && cyc(i + 2) > s.result(2 + 2 * e));
                    }
                }
                assert!((0..PRODUCTS).all(|i| s.handover >= ready(i)) && s.latency == s.handover + 1);
                // The first product into each shared accumulator starts it.
                for first in [0, 2, 4, 6].into_iter().chain((12..28).step_by(2)).chain((28..64).step_by(3)) {
                    assert!(cyc(first) <= cyc(first + 1), "K {k} L {l}: products {first}, {}", first + 1);
                }
                assert!(s.copies <= COPIES_MAX && s.copies * ii >= s.latency);
            }
        }
    }

    /// 001's 7 multipliers and 5-stage divider. II 10: 64 products on 7 lanes need
    /// ceil(64 / 7). Area in cycle 1 (with five numerators; the sixth in 2), added in 4,
    /// normalised in 5, 1/area issued in 6, into the divider in 7, back in 12 and shifted
    /// into its register; eq. (2) in 13 (added in 16). The gradients could go from 17, but
    /// then attribute 3's, added in 21, would be read by its increments' sums until 33:
    /// 12 cycles, over II. Held back a cycle (`Placement`), they go in 18, 19, 20, the 36
    /// starts and increments in 22 to 27 (the lanes free modulo 10), the last added in 30,
    /// the hand-over in 31, valid in 32: four copies. One multiplier: II 64, every slot of
    /// it taken.
    #[test]
    fn schedule_of_001s_setup() {
        let s = Schedule::new(7, 5).unwrap();
        assert_eq!((s.interval, s.latency, s.copies), (10, 32, 4));
        assert_eq!((s.normalise, s.issue[0], s.result(0), s.handover), (5, 6, 12, 31));
        assert_eq!((8..12).map(|i| s.slots[i].0).max(), Some(13));
        assert_eq!((12..28).map(|i| s.slots[i].0).min(), Some(18));
        assert_eq!((28..64).map(|i| s.slots[i].0).min(), Some(22));
        assert_eq!((28..64).map(|i| s.slots[i].0).max(), Some(27));
        assert_eq!(Schedule::new(1, 5).unwrap().interval, 64);
        assert!(Schedule::new(0, 5).is_err() && Schedule::new(8, 5).is_err() && Schedule::new(7, 0).is_err());
    }
}
