//! `triangle_queue`: rust-hdl and Verilator in lockstep with `model::triangle_queue`, every
//! output compared every cycle (the head's vertices while it is offered), at 4 entries and
//! at `gpu_top`'s 512; the triangles leave in the order they came, none lost or doubled.

use model::triangle_queue::{Triangle, TriangleQueue as Model};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::triangle_queue::TriangleQueue;
use rust_hdl::prelude::Block;
use testbenches::stimulus::random_case;
use testbenches::streams::{as_pins, triangle};
use testbenches::{count, seed, verilated_with, Dual, Mismatch, Pins, Value};

/// Stops the test on a difference between the simulators or with the model.
fn fail<T>(depth: usize, m: Mismatch) -> T {
    panic!("seed {}, depth {depth}: {m}", seed())
}

/// `n` random triangles through a queue of `depth` in both simulators beside the model.
/// The sink alternates every 200 cycles between taking a tenth and nine tenths of the
/// cycles, so that the queue fills and empties; returns the most triangles queued.
fn lockstep<U: Block + Pins>(unit: U, depth: usize, n: usize, rng: &mut ChaCha8Rng) -> usize {
    let vl = verilated_with("triangle_queue", [("DEPTH", depth as u64)]);
    let mut dual = Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut model = Model::new(depth).expect("a size the RTL is built for");
    let sent: Vec<Triangle> = (0..n).map(|_| random_case(rng).v).collect();
    let (mut next, mut offering, mut left, mut most) = (0, false, Vec::new(), 0);
    let bit = |b: bool| Value::new(1, b as u128);
    for cycle in 0.. {
        if left.len() == n {
            break;
        }
        assert!(cycle < 50 * n + 1000, "depth {depth}: {} of {n} out after {cycle} cycles", left.len());
        offering = next < n && (offering || rng.gen_bool(0.7));
        let ready = rng.gen_bool(if (cycle / 200) % 2 == 0 { 0.1 } else { 0.9 });
        let mut pins = triangle("inp", &sent[next.min(n - 1)]);
        pins.push(("inp$valid".into(), bit(offering)));
        pins.push(("out$ready".into(), bit(ready)));
        let got = dual.cycle(&as_pins(&pins)).unwrap_or_else(|m| fail(depth, m));
        let o = model.outputs();
        for (pin, want) in [("inp$ready", o.in_ready), ("out$valid", o.out.is_some()), ("idle", o.idle)] {
            dual.expect(&got, pin, &bit(want)).unwrap_or_else(|m| fail(depth, m));
        }
        if let Some(head) = o.out {
            for (pin, v) in triangle("out", &head) {
                dual.expect(&got, &pin, &v).unwrap_or_else(|m| fail(depth, m));
            }
            if ready {
                left.push(head);
            }
        }
        model.clock(offering.then_some(sent[next.min(n - 1)]), ready);
        if offering && o.in_ready {
            (next, offering) = (next + 1, false);
        }
        most = most.max(next - left.len());
    }
    assert!(left == sent, "seed {}, depth {depth}: the triangles left out of order", seed());
    most
}

/// Four entries: full and refusing most of the slow phases, the pointers wrapping every
/// four triangles.
#[test]
fn triangle_queue_of_4_vs_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let most = lockstep(TriangleQueue::<2>::default(), 4, count(), &mut rng);
    assert_eq!(most, 4, "the queue never filled");
}

/// `gpu_top`'s 512: about 120 more queued in each slow phase than a fast one drains, until
/// the queue is full and refuses.
#[test]
fn triangle_queue_of_512_vs_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed() + 1);
    let most = lockstep(TriangleQueue::<9>::default(), 512, 2 * count(), &mut rng);
    assert_eq!(most, 512, "the queue never filled");
}
