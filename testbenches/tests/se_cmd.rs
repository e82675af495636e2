//! The SE back end's span command unit (`rtl::se_cmd`, 000 Fig. 5): rust-hdl and Verilator
//! in lockstep, every cycle, against `model::se_cmd`: each command issued (the lines A, B
//! of z, R, G and B at the engines' widths, the span's ends), none for a span off screen,
//! and when: taken when the unit holds none, offered `ready_after` cycles later, issued at
//! the engines' gap (`model::cycles::se_frame`'s rule), the engines' read row that of the
//! span issued last.

use model::ctx::Ctx;
use model::cull_sort::{cull_sort, Clip, Cull};
use model::edge_walk::{edge_walk, SpanCmd};
use model::se::SeCmd as Cmd;
use model::se_cmd::{issue_gap, on_screen, ready_after, se_cmd};
use model::triangle_setup::triangle_setup;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::se_cmd::SeCmd;
use rtl::widths::{DIM, FORMATS, SE, SE_CA, SE_ZA};
use testbenches::stimulus::{extremes, random_triangle};
use testbenches::streams::{as_pins, signed, span_cmd, unsigned};
use testbenches::{count, seed, verilated, Dual, Outputs, Value};

/// The span commands of `tris` on `clip` through the model's front end.
fn spans_of(tris: impl IntoIterator<Item = [model::input::Vtx; 3]>, clip: Clip) -> Vec<SpanCmd> {
    let mut out = Vec::new();
    for v in tris {
        let Ok(sorted) = cull_sort(&v, clip, Cull::None, &FORMATS) else { continue };
        let mut ctx = Ctx::new(FORMATS);
        let setup = triangle_setup(&sorted, &mut ctx);
        out.extend(edge_walk(&setup, clip, &mut ctx).spans().copied());
    }
    out
}

/// The command on the unit's outputs.
fn command_of(o: &Outputs) -> Cmd {
    let get = |p: &str| signed(o.get(p));
    Cmd { xl: get("xl"), xr: get("xr"), a: ["za", "ra", "ga", "ba"].map(get), b: ["zb", "rb", "gb", "bb"].map(get) }
}

/// The model's command for `span` at the engines' widths (A and B taken modulo their words).
fn expected(span: &SpanCmd) -> Cmd {
    let c = se_cmd(span, &FORMATS, SE.frac);
    let w = |j: usize| if j == 0 { SE_ZA } else { SE_CA } as u32;
    Cmd {
        a: std::array::from_fn(|j| fx::wrap_s(c.a[j], w(j))),
        b: std::array::from_fn(|j| fx::wrap_s(c.b[j], w(j))),
        ..c
    }
}

/// Sends `spans` on a screen `width` wide (`inp$valid` low for a random 0 to 3 cycles
/// before each), the engines ready unless `stall`; checks each issued command against the
/// model in order, and with `stall` off each take and issue cycle against the model's rule.
fn run(dual: &mut Dual<SeCmd>, spans: &[SpanCmd], width: u32, stall: bool, rng: &mut ChaCha8Rng) {
    let want: Vec<&SpanCmd> = spans.iter().filter(|s| on_screen(s, width)).collect();
    let (gap_after, mut wait) = (ready_after(&FORMATS), 0u32);
    let (mut next, mut got, mut offered_at) = (0, 0, None);
    // The model's rule: the first cycle the unit may take a span, and the last issue.
    let (mut free, mut last_issue): (u64, Option<(u64, u32)>) = (0, None);
    let mut pending_issue: Option<u64> = None;
    let limit = 400 * (spans.len() as u64 + 10);
    while got < want.len() || next < spans.len() {
        assert!(dual.cycles() < limit, "se_cmd: {got} of {} commands after {limit} cycles", want.len());
        let cycle = dual.cycles();
        let valid = next < spans.len() && wait == 0;
        if valid && offered_at.is_none() {
            offered_at = Some(cycle);
        }
        let ready = !stall || rng.gen_bool(0.6);
        let mut pins = span_cmd("inp", &spans[next.min(spans.len() - 1)]);
        pins.push(("inp$valid".into(), Value::new(1, valid as u128)));
        pins.push(("width".into(), Value::new(DIM, width as u128)));
        pins.push(("out_ready".into(), Value::new(1, ready as u128)));
        let out = dual.cycle(&as_pins(&pins)).unwrap_or_else(|m| panic!("{m}"));
        if let Some((_, y)) = last_issue {
            assert_eq!(unsigned(out.get("rd_y")) as u32, y, "cycle {cycle}: the engines' read row");
        }
        if unsigned(out.get("out_valid")) == 1 && ready {
            let cmd = command_of(&out);
            assert_eq!(cmd, expected(want[got]), "cycle {cycle}: command {got}");
            if !stall {
                assert_eq!(Some(cycle), pending_issue, "cycle {cycle}: command {got} issued");
                last_issue = Some((cycle, want[got].y as u32));
                free = cycle + 1;
                pending_issue = None;
            }
            got += 1;
        }
        if valid && unsigned(out.get("inp$ready")) == 1 {
            let s = &spans[next];
            if !stall {
                let start = offered_at.expect("offered").max(free);
                assert_eq!(cycle, start, "span {next} taken");
                if on_screen(s, width) {
                    let ready = start + gap_after;
                    pending_issue = Some(match last_issue {
                        Some((c, y)) => ready.max(c + issue_gap(&SE, y == s.y as u32)),
                        None => ready,
                    });
                } else {
                    free = start + 1;
                }
            }
            next += 1;
            offered_at = None;
            wait = rng.gen_range(0..4);
        } else if !valid {
            wait = wait.saturating_sub(1);
        }
    }
}

/// Spans of random triangles on 320 x 240 (many off screen: vertices reach well beyond
/// it) and a sample of those of the extreme triangles on 1024 x 1024 (the xy range's corners, slivers with
/// the steepest slopes, depths and colours at their limits), in both simulators: every
/// command the model's, taken and issued on the model's cycles; and again with the engines
/// stalling.
#[test]
fn se_cmd_random_and_extreme_spans_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let clip = Clip { width: 320, height: 240 };
    // Each span takes the engines' gap, 136 cycles or more: a few hundred of each kind.
    let tris: Vec<_> = (0..count() / 50).map(|_| random_triangle(&mut rng, clip)).collect();
    let random: Vec<SpanCmd> = spans_of(tris, clip).into_iter().take(count() / 2).collect();
    let big = Clip { width: 1024, height: 1024 };
    let all = spans_of(extremes().into_iter().map(|(_, c)| c.v), big);
    let extreme: Vec<SpanCmd> = all.iter().step_by(all.len().div_ceil(count() / 4).max(1)).copied().collect();
    let vl = verilated("se_cmd");
    let off = |s: &[SpanCmd], w| s.iter().filter(|s| !on_screen(s, w)).count();
    assert!(off(&random, 320) > 10 && random.len() - off(&random, 320) > 100, "spans on and off screen");
    for (spans, width) in [(&random, 320), (&extreme, 1024)] {
        for stall in [false, true] {
            let mut dual = Dual::new(SeCmd::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
            run(&mut dual, spans, width, stall, &mut rng);
        }
    }
}
