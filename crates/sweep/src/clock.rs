//! The clock model: the scanline pipeline's clock at formats and parameters that were not
//! placed and routed.
//!
//! Each unit's Fmax was measured once, at the default design (nextpnr-ecp5, `edgepaint
//! report`, README "Units"). Elsewhere a unit's critical path is taken to scale with the
//! width of the carry chain or logic it runs through ([`critical_bits`]): the delay at a
//! design is the measured delay times the ratio of the widths. The pipeline runs at its
//! slowest unit's clock, times the ratio of `raster_top`'s measured Fmax to its slowest
//! unit's at the default (routing the composed design costs or gains that much).

use crate::area::Design;
use crate::row::Source;
use fx::Formats;
use rtl::config::Widths;

/// ECP5 Fmax in MHz of each unit at the default design (class 10, K = 7, L = 25), as
/// placed and routed by the soak (README, "Units"). Setup's is its own, routed alone at
/// stop 57 before its decoders read the counters' registers (its critical path copy 4's
/// counter through copy 5's next count into the result-valid decode, 13.6 ns, 11.8 of it
/// routing); the divider's stage is one restoring step.
pub const MEASURED_MHZ: [(&str, f64); 6] = [
    ("cull_sort", 115.9),
    ("triangle_setup", 73.8),
    ("divider", 105.1),
    ("edge_walk", 118.9),
    ("span", 113.5),
    ("pixel_out", 142.2),
];
/// `raster_top`'s ECP5 Fmax at the default design, MHz (LFE5U-45F, router1, seed 1, stop 63:
/// 38.3 before stop 54's geometry registers, 55.7 before the multipliers were split, 65.0
/// before setup's geometry moved with the triangle, 68.5 before the span FIFO's head register
/// and setup's decoders from the counters' registers, 70.1 before setup's schedule as tokens,
/// its `run` from a register and span's depth test without its adder, 81.7 before the count's
/// comparisons moved into setup's geometry word, which took setup off the critical path and
/// left span's command handshake into the span FIFO's head register, placed worse; 76.9
/// before span's `at_last` register and the span FIFO's registered flags, which left span's
/// tests of a command coming through the FIFO's pass-through multiplexer critical; 79.8
/// before the FIFO lost its pass-through, which leaves setup's normalise critical: the
/// area's absolute value and its leading-one search into the shift register `nsh`).
pub const PIPELINE_MHZ: f64 = 83.0;

/// `gpu_top`'s ECP5 Fmax at the default design, MHz, placed and routed whole (LFE5U-85F,
/// nextpnr's router1; README, "Units"): its critical path is the command parser's (the
/// triangle count against the buffer's, the index record's end and fault checks, the next
/// vertex index into the tag RAM's read address). Before `pixel_bus`'s input registers
/// (stop 38) it was 30.4 MHz, on `pixel_bus`'s path into span; 41.8 MHz at stop 38, 39.4 at
/// the soak of stop 54 (today's RTL).
pub const GPU_TOP_MHZ: f64 = 39.4;

/// The barycentric pipeline's ECP5 Fmax (`raster_top` with `METHOD = 1`: `cull_sort`,
/// `rtl::vector` at one lane, `pixel_out`) at the default design, MHz, placed and routed
/// whole (LFE5U-45F, router2; README, "Units"): its critical path is the vector unit's scout
/// (a probe's edge function less a chunk's step, the reject test, the probes' moves and the
/// row found, into the probes' registers; 50.5 MHz routed alone, 62.8 with stop 39's box walk).
pub const VECTOR_PIPELINE_MHZ: f64 = 48.2;

/// The same at four lanes (`--param LANES=4`, LFE5U-85F, router2, stop 42): its critical
/// path is the vector unit's stall, from a lane's output valid through `pixel_out`'s ready
/// into the hold of every lane's 25-stage divider (17.5 of its 24.4 ns the hold net's
/// routing to its fan-out).
pub const VECTOR_PIPELINE_4_MHZ: f64 = 41.0;

/// The barycentric pipeline's clock at `lanes` lanes (1, 2, 4 or 8) at the default design,
/// MHz, and where it comes from: routed at one lane and four ([`VECTOR_PIPELINE_MHZ`],
/// [`VECTOR_PIPELINE_4_MHZ`]); at two and eight its period modelled as linear in the lanes
/// through those two, the stall net's fan-out growing with them (two lanes: 45.5 MHz, where
/// the vector unit alone at two lanes routed at 45.7). `None` for other lane counts.
pub fn vector_pipeline_mhz(lanes: u32) -> Option<(f64, Source)> {
    let (one, four) = (1.0 / VECTOR_PIPELINE_MHZ, 1.0 / VECTOR_PIPELINE_4_MHZ);
    match lanes {
        1 => Some((VECTOR_PIPELINE_MHZ, Source::Measured)),
        4 => Some((VECTOR_PIPELINE_4_MHZ, Source::Measured)),
        2 | 8 => Some((1.0 / (one + (four - one) * f64::from(lanes - 1) / 3.0), Source::Modelled)),
        _ => None,
    }
}

/// The SE back end's ECP5 Fmax (`raster_top` with `METHOD = 2`: the scanline front end,
/// `se_cmd`, one engine) at the default design, MHz, placed and routed whole (LFE5U-85F,
/// router2, stop 42; README, "Units"): its critical path runs from the span FIFO's read
/// through `se_cmd`'s test of a span's ends against the screen into the enables of its
/// serial multiplier's registers, 20.2 of its 23.2 ns routing. Five and 16 engines fit no
/// ECP5 with the report's room for routing; the sweep takes this clock for them.
pub const SE_PIPELINE_MHZ: f64 = 43.1;

/// The design [`MEASURED_MHZ`] and [`PIPELINE_MHZ`] were measured at: size class
/// `fx::RTL_CLASS` at its default formats, K = 7, L = `model::divider::LATENCY` (25).
pub fn measured_design() -> Design {
    Design { class: fx::RTL_CLASS, formats: Formats::for_n(fx::RTL_CLASS), k: 7, l: model::divider::LATENCY }
}

/// `raster_top`'s clock at `d`, MHz, and where the figure comes from: the routed
/// [`PIPELINE_MHZ`] at [`measured_design`] ([`Source::Measured`]), [`pipeline_mhz`]
/// elsewhere ([`Source::Modelled`]).
pub fn raster_top_mhz(d: &Design) -> (f64, Source) {
    let default = measured_design();
    if *d == default {
        (PIPELINE_MHZ, Source::Measured)
    } else {
        (pipeline_mhz(d, &default), Source::Modelled)
    }
}

/// The width, in bits, of what a unit's critical path runs through, the delay's measure:
/// cull_sort's sort of the vertices by y (xy bits); setup's geometry (its scanline centres'
/// adders, `mul_b` bits: the narrow domain); the divider's stage, ceil((div_q - 1) / L) restoring steps of a `div_d`-bit
/// subtraction in series; the edge walker's start decision at the hand-over (`edge_d`);
/// span's depth rounding and range test (`z_acc`, `c_acc`, the wider); pixel_out's depth
/// compare (`depth`).
pub fn critical_bits(unit: &str, d: &Design) -> f64 {
    let w = Widths::of(d.class, &d.formats);
    let bits = match unit {
        "cull_sort" => w.xy,
        "triangle_setup" => w.mul_b,
        "divider" => (w.div_q - 1).div_ceil(d.l.max(1) as usize) * w.div_d,
        "edge_walk" => w.edge_d,
        "span" => w.z_acc.max(w.c_acc),
        _ => w.depth,
    };
    bits as f64
}

/// The modelled clock of the scanline pipeline at `d`, MHz; `default` is the design the
/// Fmax were measured at.
pub fn pipeline_mhz(d: &Design, default: &Design) -> f64 {
    let slowest = |d: &Design| {
        MEASURED_MHZ
            .iter()
            .map(|(unit, mhz)| mhz * critical_bits(unit, default) / critical_bits(unit, d))
            .fold(f64::INFINITY, f64::min)
    };
    slowest(d) * PIPELINE_MHZ / slowest(default)
}

#[cfg(test)]
mod tests {
    use super::*;
    use fx::Formats;
    use model::divider::LATENCY;

    #[test]
    fn vector_clock_is_routed_at_one_and_four_lanes_and_modelled_between() {
        assert_eq!(vector_pipeline_mhz(1), Some((VECTOR_PIPELINE_MHZ, Source::Measured)));
        assert_eq!(vector_pipeline_mhz(4), Some((VECTOR_PIPELINE_4_MHZ, Source::Measured)));
        let (two, s2) = vector_pipeline_mhz(2).unwrap();
        let (eight, s8) = vector_pipeline_mhz(8).unwrap();
        assert_eq!((s2, s8), (Source::Modelled, Source::Modelled));
        assert!(VECTOR_PIPELINE_4_MHZ < two && two < VECTOR_PIPELINE_MHZ, "{two}");
        assert!((two - 45.5).abs() < 0.05 && eight < VECTOR_PIPELINE_4_MHZ, "{two} {eight}");
        assert_eq!(vector_pipeline_mhz(3), None);
    }

    #[test]
    fn raster_top_runs_at_the_routed_clock_at_the_default_and_the_modelled_one_elsewhere() {
        let d = design(10, LATENCY);
        assert_eq!(d, measured_design());
        assert_eq!(raster_top_mhz(&d), (PIPELINE_MHZ, Source::Measured));
        let wide = design(12, LATENCY);
        assert_eq!(raster_top_mhz(&wide), (pipeline_mhz(&wide, &d), Source::Modelled));
        // K moves no critical path in the model: the same clock, but not a routed one.
        let k1 = Design { k: 1, ..d };
        let (mhz, source) = raster_top_mhz(&k1);
        assert!((mhz - PIPELINE_MHZ).abs() < 1e-9 && source == Source::Modelled, "{mhz} {source:?}");
    }

    fn design(class: u32, l: u32) -> Design {
        Design { class, formats: Formats::for_n(class), k: 7, l }
    }

    #[test]
    fn the_default_runs_at_its_measured_clock_and_wider_or_shallower_designs_slower() {
        let d = design(10, LATENCY);
        assert!((pipeline_mhz(&d, &d) - PIPELINE_MHZ).abs() < 1e-9);
        assert!(pipeline_mhz(&design(12, LATENCY), &d) < PIPELINE_MHZ);
        // One divider stage does all 25 stages' steps in series: it sets the clock, scaled
        // from the default's slowest unit.
        let one = pipeline_mhz(&design(10, 1), &d);
        let div = MEASURED_MHZ[2].1 * critical_bits("divider", &d) / critical_bits("divider", &design(10, 1));
        let slowest = MEASURED_MHZ.iter().map(|&(_, mhz)| mhz).fold(f64::INFINITY, f64::min);
        assert!((one - div * PIPELINE_MHZ / slowest).abs() < 1e-9, "{one} {div}");
        assert!(one < PIPELINE_MHZ / 2.0);
    }
}
