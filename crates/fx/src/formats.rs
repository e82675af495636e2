//! The format of every quantity in edgepaint's fixed-point pipelines.
//!
//! `n = max(clog2(max(width, height)), 10)` ([`resolution_bits`]); `s` = subpixel bits (default 4). Defaults
//! are [`Formats::for_resolution`]; [`Formats::wide`] adds precision everywhere
//! (used to show that the pipelines converge on the float reference).
//!
//! | field | default | quantity | written by | read by | into it | overflow |
//! |---|---|---|---|---|---|---|
//! | `xy` | S(n+1).s half-up | vertex x, y in pixels | input | cull_sort, setup, edge_walk, vector | half-up | input checked (reject) |
//! | `z` | S1.16 half-up | vertex z; its fraction bits are the depth buffer's width | input | setup, span, vector | half-up | input checked (reject) |
//! | `color` | U8.0 half-up saturate | vertex R, G, B | input | setup, vector | half-up | input checked (reject) |
//! | `inv_w` | U1.15 half-up | w_min / w per vertex (1 for the nearest) | input | vector (004 eq. 5-6) | half-up | input checked (reject) |
//! | `ooa` | U1.24 | mantissa of OneOverArea (001) and of 1/sum in `vector`, in [1/2, 1], with a shift | divider | setup, vector | floor (divider) | cannot |
//! | `ooa_d` | S21.(n+25) | OneOverArea x edge dx or dy (the first products of 001 eq. 2) | setup | setup | floor | wrap (modular) |
//! | `dz` | S(1+s).(n+24) | dz/dx, dz/dy and the edge increments of z | setup | edge_walk, span | floor | wrap (modular) |
//! | `z_acc` | S1.(n+24) | z accumulators (edge and span) | setup, edge_walk | span | floor | wrap (modular) |
//! | `dc` | S(9+s).(n+12) | dC/dx, dC/dy and the edge increments of R, G, B | setup | edge_walk, span | floor | wrap (modular) |
//! | `c_acc` | S9.(n+12) | colour accumulators | setup, edge_walk | span | floor | wrap (modular) |
//! | `bary` | S1.(n+16) | barycentric a, b (004 eq. 3) and their perspective-corrected forms | vector | vector | floor | wrap |
//!
//! **Modular arithmetic.** Gradients, increments and accumulators only ever
//! meet through `+`, `-`, `*` and floor shifts, which commute with reduction
//! modulo a power of two. Their registers may therefore wrap: the value finally
//! emitted (a depth or colour at a pixel inside the triangle, always in range)
//! is right whenever the same computation without wrapping would be right,
//! with one condition: a product whose other factor has fraction bits carries
//! the wrap into the fraction. Start values multiply gradients by subpixel
//! offsets (`s` fraction bits), and gradients are `ooa_d` times attribute
//! differences (`z.frac` or `color.frac` fraction bits), so
//! `dz.int >= z_acc.int + s`, `dc.int >= c_acc.int + s` and
//! `ooa_d.int >= max(dz.int + z.frac, dc.int + color.frac)`: the modular minimum
//! ([`Formats::modular_ints`]), which the defaults' rules give. Beyond that, `dc` needs no more integer bits however steep a
//! sliver's gradient is. A workload whose values all fit fewer integer bits may use them
//! (`edgepaint fit` takes them from the ranges the models saw, [`Formats::narrowed`]): the
//! condition then no longer holds, [`Formats::check`] asks only for one integer bit, and
//! the models' analysis mode reports every triangle in which such a quantity wrapped. Values that are *compared* (positions, the z clip, the colour
//! clamp) are never wrapped. The models' analysis mode checks this per
//! triangle: it records which registers wrapped and compares every emitted
//! depth and colour with the exact value.
//!
//! Exact quantities (edge deltas, twice the area, edge functions, the edge
//! walk's quotient and remainder) take their widths from `xy` and are not
//! configurable: they are derived in [`Derived`].

use crate::fmt::{clog2, Fmt, MAX_BITS};
use serde::{Deserialize, Serialize};

/// The format of every configurable quantity. JSON: an object whose keys are
/// the field names and whose values are formats in the house notation
/// (`"S11.4 half-up"`); keys left out take their defaults for the resolution.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Formats {
    pub xy: Fmt,
    pub z: Fmt,
    pub color: Fmt,
    pub inv_w: Fmt,
    pub ooa: Fmt,
    pub ooa_d: Fmt,
    pub dz: Fmt,
    pub z_acc: Fmt,
    pub dc: Fmt,
    pub c_acc: Fmt,
    pub bary: Fmt,
}

/// Which of the quantities that follow from others ([`Formats::follow`]) are given as
/// they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Given {
    pub z_acc: bool,
    pub dz: bool,
    pub c_acc: bool,
    pub dc: bool,
    pub ooa_d: bool,
}

impl Given {
    /// None given: all derived.
    pub const NONE: Given = Given { z_acc: false, dz: false, c_acc: false, dc: false, ooa_d: false };
}

/// Subpixel bits of the default vertex format (1/16 pixel, as is usual).
pub const SUBPIXEL_BITS: u32 = 4;

/// The size class the default formats are derived from:
/// `n = clog2(max(width, height))`, but at least [`RTL_CLASS`], so that every
/// screen up to 1024 x 1024 shares the formats the RTL is built with.
pub const fn resolution_bits(width: u32, height: u32) -> u32 {
    class_at_least(width, height, RTL_CLASS)
}

/// `clog2(max(width, height))`, at least `floor`.
const fn class_at_least(width: u32, height: u32, floor: u32) -> u32 {
    let d = if width > height { width } else { height };
    let n = clog2(d as u64);
    if n < floor {
        floor
    } else {
        n
    }
}

/// The size class of the emitted RTL (rust-hdl widths are compile-time
/// constants): screens up to 2^10 = 1024 pixels wide and high, which covers
/// 320x240 to 001's 800x600.
pub const RTL_CLASS: u32 = 10;

/// The smallest size class a design may have (`rtl::config::CLASS_MIN`, `edgepaint fit`):
/// screens up to 256 x 256. Below it the RTL is not proven: its custom-build lockstep test
/// (`testbenches/tests/raster_top.rs`, frames of 24 x 16 and 40 x 30) has run at classes 9
/// and 8 (classes down to 6 would hold those frames, but have not been run), and a smaller
/// screen saves little (the per-triangle units do not shrink with the class).
pub const SMALLEST_CLASS: u32 = 8;

/// The smallest size class that holds a `width` x `height` screen:
/// `clog2(max(width, height))`, at least [`SMALLEST_CLASS`]. Unlike [`resolution_bits`] not
/// raised to [`RTL_CLASS`]: the class `edgepaint fit` gives a workload (a 320 x 240 screen
/// gets class 9, 512 x 512 counters and addresses). The default formats of every screen
/// stay [`resolution_bits`]'.
pub const fn smallest_class(width: u32, height: u32) -> u32 {
    class_at_least(width, height, SMALLEST_CLASS)
}

/// Widths of the exact (non-configurable) quantities, derived from the formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Derived {
    /// Edge dx, dy (differences of two vertices): signed bits.
    pub delta_bits: u32,
    /// Twice the signed area in subpixel units (exact): signed bits.
    pub area_bits: u32,
    /// Edge functions at pixel centres, the numerators of 004 eq. 3 (exact): signed bits.
    pub edge_fn_bits: u32,
    /// Pixel positions anywhere in the coordinate range: signed bits.
    pub pixel_bits: u32,
    /// Divider dividend, divisor and quotient: the widest of its seven uses.
    pub div_dividend_bits: u32,
    pub div_divisor_bits: u32,
    pub div_quotient_bits: u32,
}

impl Formats {
    /// Defaults for a `width` x `height` screen.
    pub fn for_resolution(width: u32, height: u32) -> Formats {
        Formats::for_n(resolution_bits(width, height))
    }

    /// Defaults for screens up to 2^n pixels wide and high. A `const fn`, so
    /// that RTL port widths can be read off it at compile time:
    /// `Signed<{ Formats::for_n(10).xy.bits() as usize }>`. The knobs (`xy`, `z`, `color`,
    /// `inv_w`, `ooa`, `bary`) are set here; the rest follow from them ([`Formats::follow`]).
    pub const fn for_n(n: u32) -> Formats {
        let s = SUBPIXEL_BITS;
        let unset = Fmt::s(0, 0);
        Formats {
            xy: Fmt::s(n + 1, s).half_up(),
            z: Fmt::s(1, 16).half_up(),
            color: Fmt::u(8, 0).half_up().saturating(),
            inv_w: Fmt::u(1, 15).half_up(),
            ooa: Fmt::u(1, 24),
            ooa_d: unset,
            dz: unset,
            z_acc: unset,
            dc: unset,
            c_acc: unset,
            bary: Fmt::s(1, n + 16),
        }
        .follow(n, Given::NONE)
    }

    /// `self` with every dependent quantity not in `given` derived, by the defaults' rules,
    /// from the knobs for size class `n` (s = `xy.frac`):
    ///
    /// | quantity | rule | class 10 default |
    /// |---|---|---|
    /// | `z_acc` | S1.(n + z.frac + 8) | S1.34 |
    /// | `dz` | S(z_acc.int + s).(z_acc.frac): the modular minimum | S5.34 |
    /// | `c_acc` | S9.(n + color.frac + 12) | S9.22 |
    /// | `dc` | S(c_acc.int + s).(c_acc.frac) | S13.22 |
    /// | `ooa_d` | S(max(dz.int + z.frac, dc.int + color.frac)).(max(n + ooa.frac + 1, dc.frac, dz.frac - z.frac)) | S21.35 |
    ///
    /// So a formats file may name only the knobs a user thinks in (`{"xy": "S11.8
    /// half-up"}` for 8 subpixel bits) and the accumulators, gradients and products widen
    /// with them; a quantity it names is kept as given (and checked: [`Formats::check`]).
    pub const fn follow(self, n: u32, given: Given) -> Formats {
        const fn max(a: u32, b: u32) -> u32 {
            if a > b {
                a
            } else {
                b
            }
        }
        let mut f = self;
        let s = f.xy.frac;
        if !given.z_acc {
            f.z_acc = Fmt::s(1, n + f.z.frac + 8);
        }
        if !given.dz {
            f.dz = Fmt::s(f.z_acc.int + s, f.z_acc.frac);
        }
        if !given.c_acc {
            f.c_acc = Fmt::s(9, n + f.color.frac + 12);
        }
        if !given.dc {
            f.dc = Fmt::s(f.c_acc.int + s, f.c_acc.frac);
        }
        if !given.ooa_d {
            let int = max(f.dz.int + f.z.frac, f.dc.int + f.color.frac);
            let frac = max(max(n + f.ooa.frac + 1, f.dc.frac), f.dz.frac.saturating_sub(f.z.frac));
            f.ooa_d = Fmt::s(int, frac);
        }
        f
    }

    /// The smallest integer bits the modular condition allows for `dz`, `dc`
    /// and `ooa_d`, given the other formats (see the module doc).
    pub fn modular_ints(&self) -> (u32, u32, u32) {
        let s = self.xy.frac;
        let (dz, dc) = (self.z_acc.int + s, self.c_acc.int + s);
        (dz, dc, (dz + self.z.frac).max(dc + self.color.frac))
    }

    /// Far more precision than any display needs: 16 subpixel bits, 24-bit
    /// depth, 8 colour fraction bits, and 16 more fraction bits downstream.
    /// The fixed-point pipelines at these formats must agree with the float
    /// reference to within documented ties.
    pub fn wide(width: u32, height: u32) -> Formats {
        let d = Formats::for_resolution(width, height);
        let more = |f: Fmt, k: u32| Fmt { frac: f.frac + k, ..f };
        let mut w = Formats {
            xy: more(d.xy, 12),
            z: more(d.z, 8),
            color: more(d.color, 8),
            inv_w: more(d.inv_w, 16),
            ooa: more(d.ooa, 16),
            ooa_d: more(d.ooa_d, 8),
            dz: more(d.dz, 16),
            z_acc: more(d.z_acc, 16),
            dc: more(d.dc, 16),
            c_acc: more(d.c_acc, 16),
            bary: more(d.bary, 16),
        };
        let (dz, dc, ooa_d) = w.modular_ints();
        (w.dz.int, w.dc.int, w.ooa_d.int) = (dz, dc, ooa_d);
        w
    }

    /// Defaults for the resolution with the keys of a JSON object applied on top, and the
    /// quantities it does not name that follow from those it does derived again
    /// ([`Formats::follow`]).
    pub fn with_overrides(width: u32, height: u32, json: &serde_json::Value) -> Result<Formats, String> {
        let f = Formats::over(resolution_bits(width, height), json)?;
        f.check(width, height)?;
        Ok(f)
    }

    /// [`Formats::with_overrides`] for a design of size class `class` (screens up to
    /// 2^class x 2^class): the keys over `Formats::for_n(class)`, the rest following for
    /// `class` (a class below [`RTL_CLASS`] too: `rtl`'s `build.rs`, `edgepaint fit`).
    pub fn with_overrides_at(class: u32, json: &serde_json::Value) -> Result<Formats, String> {
        if class > 16 {
            return Err(format!("size class {class}: at most 16 (screens up to 65536 x 65536)"));
        }
        let f = Formats::over(class, json)?;
        let side = 1u32 << class;
        f.check(side, side)?;
        Ok(f)
    }

    /// `Formats::for_n(class)` with the keys of `json` on top and the rest following
    /// (unchecked).
    fn over(class: u32, json: &serde_json::Value) -> Result<Formats, String> {
        let mut v = serde_json::to_value(Formats::for_n(class)).expect("formats serialise");
        let obj = json.as_object().ok_or("a formats file must be a JSON object mapping quantities to formats")?;
        let target = v.as_object_mut().expect("formats serialise to an object");
        for (k, val) in obj {
            if k == "texture" {
                // The texture unit's formats: `TexFormats::from_formats_file`.
                continue;
            }
            if !target.contains_key(k) {
                let known: Vec<&str> = target.keys().map(String::as_str).chain(["texture"]).collect();
                return Err(format!("unknown quantity \"{k}\" (known: {})", known.join(", ")));
            }
            target.insert(k.clone(), val.clone());
        }
        let f: Formats = serde_json::from_value(v).map_err(|e| e.to_string())?;
        let named = |k: &str| obj.contains_key(k);
        let given = Given {
            z_acc: named("z_acc"),
            dz: named("dz"),
            c_acc: named("c_acc"),
            dc: named("dc"),
            ooa_d: named("ooa_d"),
        };
        Ok(f.follow(class, given))
    }

    /// The quantities narrower than the defaults' rules make them for every workload, in
    /// which a wrap is therefore not known to be harmless: `dz`, `dc` and `ooa_d` below the
    /// modular minimum ([`Formats::modular_ints`]), `z_acc` below S1 (z's guard band) and
    /// `c_acc` below S9. Empty at every class's defaults and at [`Formats::wide`]; a fitted
    /// design's integer bits from a workload's ranges (`edgepaint fit`) may be here, and the
    /// models' analysis mode reports every triangle in which one of them wrapped.
    pub fn narrowed(&self) -> Vec<&'static str> {
        let (dz, dc, ooa_d) = self.modular_ints();
        [
            ("dz", self.dz.int < dz),
            ("dc", self.dc.int < dc),
            ("ooa_d", self.ooa_d.int < ooa_d),
            ("z_acc", self.z_acc.int < 1),
            ("c_acc", self.c_acc.int < 9),
        ]
        .into_iter()
        .filter_map(|(q, below)| below.then_some(q))
        .collect()
    }

    /// Every format as (name, format), in declaration order.
    pub fn named(&self) -> [(&'static str, Fmt); 11] {
        [
            ("xy", self.xy),
            ("z", self.z),
            ("color", self.color),
            ("inv_w", self.inv_w),
            ("ooa", self.ooa),
            ("ooa_d", self.ooa_d),
            ("dz", self.dz),
            ("z_acc", self.z_acc),
            ("dc", self.dc),
            ("c_acc", self.c_acc),
            ("bary", self.bary),
        ]
    }

    /// Widths of the exact quantities.
    pub const fn derived(&self) -> Derived {
        const fn max(a: u32, b: u32) -> u32 {
            if a > b {
                a
            } else {
                b
            }
        }
        let delta_bits = self.xy.bits() + 1;
        let area_bits = 2 * delta_bits;
        let edge_fn_bits = area_bits + 1;
        let pixel_bits = self.xy.int + 2;
        // The divider serves three kinds of division (see `model::divider`):
        // the reciprocal mantissa 2^(area_bits + ooa.frac - 2) / |area| normalised,
        // the edge start (x fraction * dy + dx * t) / (2^s * dy) and the step dx / dy.
        let recip_dividend = area_bits + self.ooa.frac;
        let start_dividend = delta_bits + self.xy.frac + 2;
        Derived {
            delta_bits,
            area_bits,
            edge_fn_bits,
            pixel_bits,
            div_dividend_bits: max(recip_dividend, start_dividend),
            div_divisor_bits: max(area_bits, delta_bits + self.xy.frac),
            div_quotient_bits: max(self.ooa.frac + 2, delta_bits + 1),
        }
    }

    /// Whether these formats can work at all for a `width` x `height` screen;
    /// the error says which format is impossible and why.
    pub fn check(&self, width: u32, height: u32) -> Result<(), String> {
        let d = width.max(height) as f64;
        let need = |ok: bool, name: &str, f: Fmt, why: String| {
            if ok {
                Ok(())
            } else {
                Err(format!("{name} = {f}: {why}"))
            }
        };
        for (name, f) in self.named() {
            need(f.bits() <= MAX_BITS, name, f, format!("wider than the {MAX_BITS} bits the models compute in"))?;
        }
        let (xy, z) = (self.xy, self.z);
        need(xy.signed, "xy", xy, "vertex coordinates must be signed (the guard band reaches below 0)".into())?;
        let (lo, hi) = (-d / 2.0, width.max(height) as f64 + d / 2.0);
        need(
            xy.from_f64(lo).is_some() && xy.from_f64(hi).is_some(),
            "xy",
            xy,
            format!("must hold the guard band [{lo}, {hi}] of a {width}x{height} screen"),
        )?;
        need(xy.frac >= 1, "xy", xy, "needs at least one subpixel bit (pixel centres lie at .5)".into())?;
        need(
            z.signed && z.int >= 1,
            "z",
            z,
            "must be signed with an integer bit to hold the guard band [-0.5, 1.5]".into(),
        )?;
        need((1..=32).contains(&z.frac), "z", z, "its fraction bits are the depth buffer's width: 1 to 32".into())?;
        need(
            !self.color.signed && self.color.int >= 8,
            "color",
            self.color,
            "must be unsigned with 8 integer bits (0..255)".into(),
        )?;
        need(
            !self.inv_w.signed && self.inv_w.int >= 1,
            "inv_w",
            self.inv_w,
            "must be unsigned with an integer bit to hold 1.0".into(),
        )?;
        need(
            !self.ooa.signed && self.ooa.int == 1 && self.ooa.frac >= 2,
            "ooa",
            self.ooa,
            "is a reciprocal mantissa in [1/2, 1]: U1.<frac>".into(),
        )?;
        need(self.ooa_d.signed, "ooa_d", self.ooa_d, "must be signed".into())?;
        for (name, g, acc) in [("dz", self.dz, self.z_acc), ("dc", self.dc, self.c_acc)] {
            need(g.signed && acc.signed, name, g, "gradients and accumulators must be signed".into())?;
            need(g.frac == acc.frac, name, g, format!("must have the fraction bits of its accumulator {acc}"))?;
        }
        // Below the modular minimum (`modular_ints`) a wrap is no longer harmless, but the
        // formats still work where nothing wraps: a workload's ranges (`narrowed`).
        for (name, g) in [("dz", self.dz), ("dc", self.dc), ("ooa_d", self.ooa_d)] {
            need(g.int >= 1, name, g, "needs at least 1 integer bit".into())?;
        }
        need(
            self.z_acc.frac >= z.frac,
            "z_acc",
            self.z_acc,
            format!("needs at least the {} fraction bits of z", z.frac),
        )?;
        need(self.c_acc.int >= 8, "c_acc", self.c_acc, "needs 8 integer bits to hold 0..255".into())?;
        need(
            self.c_acc.frac >= self.color.frac,
            "c_acc",
            self.c_acc,
            "needs at least the fraction bits of color".into(),
        )?;
        need(
            self.ooa_d.frac >= self.dc.frac && self.ooa_d.frac + z.frac >= self.dz.frac,
            "ooa_d",
            self.ooa_d,
            "needs at least the fraction bits of dc (and of dz less those of z)".into(),
        )?;
        need(
            self.bary.signed && self.bary.int >= 1,
            "bary",
            self.bary,
            "must be signed with an integer bit to hold 1.0".into(),
        )?;
        let dv = self.derived();
        need(
            dv.div_dividend_bits + 8 <= MAX_BITS,
            "xy",
            xy,
            "too wide: the divider's dividend would not fit 128-bit arithmetic".into(),
        )?;
        Ok(())
    }
}

/// What a copy of the scanline RTL is built at, and what `model::raster_top` draws at: a
/// size class (screens up to 2^class x 2^class) and the formats of every quantity.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Build {
    pub class: u32,
    pub formats: Formats,
}

impl Build {
    /// Size class `class` at the default formats for it.
    pub const fn of_class(class: u32) -> Build {
        Build { class, formats: Formats::for_n(class) }
    }

    /// The smallest class that draws a `width` x `height` screen ([`resolution_bits`], at
    /// least [`RTL_CLASS`]) at its default formats.
    pub const fn for_screen(width: u32, height: u32) -> Build {
        Build::of_class(resolution_bits(width, height))
    }
}

/// The default build: size class [`RTL_CLASS`] at its default formats.
impl Default for Build {
    fn default() -> Build {
        Build::of_class(RTL_CLASS)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The defaults are their knobs followed by the rules, and the rules give what the
    /// modular condition asks for and no more.
    #[test]
    fn formats_defaults_are_their_knobs_followed() {
        for n in 10..=16 {
            let d = Formats::for_n(n);
            assert_eq!(d.ooa_d, Fmt::s(21, n + 25));
            assert_eq!(
                (d.dz, d.z_acc, d.dc, d.c_acc),
                (Fmt::s(5, n + 24), Fmt::s(1, n + 24), Fmt::s(13, n + 12), Fmt::s(9, n + 12))
            );
            let (dz, dc, ooa_d) = d.modular_ints();
            assert_eq!((d.dz.int, d.dc.int, d.ooa_d.int), (dz, dc, ooa_d));
        }
    }

    #[test]
    fn formats_defaults_follow_the_resolution() {
        let f = Formats::for_resolution(640, 480);
        assert_eq!(f.xy.to_string(), "S11.4 [16] half-up");
        assert_eq!(Formats::for_resolution(4096, 4096).xy.to_string(), "S13.4 [18] half-up");
        for (w, h) in [(1, 1), (320, 240), (640, 480), (1024, 768), (4096, 4096)] {
            Formats::for_resolution(w, h).check(w, h).unwrap();
            Formats::wide(w, h).check(w, h).unwrap();
        }
    }

    #[test]
    fn formats_json_overrides_and_rejects_impossible_formats() {
        let j = serde_json::json!({"dc": "S13.30", "c_acc": "S9.30"});
        let f = Formats::with_overrides(640, 480, &j).unwrap();
        assert_eq!(f.dc, Fmt::s(13, 30));
        // Only the knobs: the accumulators, gradients and products follow.
        let f = Formats::with_overrides(640, 480, &serde_json::json!({"xy": "S11.8 half-up"})).unwrap();
        assert_eq!((f.dz, f.dc, f.ooa_d), (Fmt::s(9, 34), Fmt::s(17, 22), Fmt::s(25, 35)));
        let f = Formats::with_overrides(640, 480, &serde_json::json!({"z": "S1.24 half-up", "color": "U8.2"})).unwrap();
        assert_eq!((f.z_acc, f.dz, f.c_acc, f.dc), (Fmt::s(1, 42), Fmt::s(5, 42), Fmt::s(9, 24), Fmt::s(13, 24)));
        assert_eq!(f.ooa_d, Fmt::s(29, 35), "dz.int + z.frac = 29 integer bits, n + ooa.frac + 1 fraction bits");
        let cases = [
            (serde_json::json!({"xy": "S8.4"}), "guard band"),
            (serde_json::json!({"dc": "S13.10"}), "fraction bits of its accumulator"),
            (serde_json::json!({"dc": "S0.22"}), "at least 1 integer bit"),
            (serde_json::json!({"zz": "S1.16"}), "unknown quantity \"zz\""),
            (serde_json::json!({"z": "U1.16"}), "must be signed"),
            (serde_json::json!({"z": "S1.40"}), "depth buffer"),
            (serde_json::json!({"color": "U7.0"}), "8 integer bits"),
            (serde_json::json!({"ooa": "U2.20"}), "mantissa"),
            (serde_json::json!({"xy": "S11.x"}), "not a whole number"),
        ];
        for (j, want) in cases {
            let e = Formats::with_overrides(640, 480, &j).unwrap_err();
            assert!(e.contains(want), "{j}: got {e:?}, want {want:?}");
        }
    }
}
