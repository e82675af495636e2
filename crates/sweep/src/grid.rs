//! The design points a sweep runs: a grid file, or [`Grid::default`].
//!
//! **The grid file** (JSON; every key optional):
//!
//! ```json
//! {
//!   "methods": ["scanline", "vector"],
//!   "sensitivity": { "xy.frac": [2, 3, 4, 5, 6, 7, 8], "lanes": [1, 2, 4, 8, 16] },
//!   "joint": { "samples": 12, "seed": 1 }
//! }
//! ```
//!
//! * `methods`: `scanline` (001/003: setup, edge walk, span), `vector` (004) and `se`
//!   (the scanline pipeline's spans drawn by 000's shading engines, `model::se::array`:
//!   the scanline's format knobs, its engines' words sized by the formats).
//! * `sensitivity`: one knob at a time, each over its values. A knob is a quantity's
//!   fraction bits, `<quantity>.frac` (the quantities of `fx::Formats`: `xy.frac` is the
//!   subpixel bits, `z.frac` the depth buffer's width; `z_acc.frac` sets `dz`'s too and
//!   `c_acc.frac` `dc`'s, as the two must match), or a method's parameter: `K` (setup's
//!   multipliers) and `L` (the divider's stages) for scanline, `lanes` for vector. A
//!   format knob is swept with every other quantity wide (`fx::Formats::wide`), so the
//!   error is the knob's alone (`se` sweeps them around the default formats instead: its
//!   engines' words hold 32 bits at most, which the wide formats exceed); a parameter knob
//!   at the default formats. A method runs
//!   only the knobs it has (vector has no accumulators, scanline no barycentrics).
//!   A scanline point may also set a quantity's integer bits, `<quantity>.int` for `dz`, `dc`,
//!   `ooa_d`, `z_acc` and `c_acc` (`edgepaint fit` sets them from a workload's ranges):
//!   applied last, over what the rules give, and not raised to the modular minimum.
//! * `joint`: `samples` points per method with every knob of the method drawn at random
//!   (seed `seed`) from its values, the other quantities following by the defaults' rules
//!   (`fx::Formats::follow`), an accumulator's draw raised to its input's fraction bits
//!   where it is below them (`z_acc.frac` to `z.frac`, `c_acc.frac` to `color.frac`): the
//!   cloud the Pareto front is drawn from.
//!
//! Each method also runs the default design (`default`). After a format knob is applied,
//! the integer bits the modular condition needs (`dz`, `dc`, `ooa_d`) are raised to it
//! (unless the point sets them, `<quantity>.int`);
//! a point whose formats are impossible for a scene (`fx::Formats::check`) is an error
//! that names the point.

use fx::{Fmt, Formats, Given};
use rand::{Rng, SeedableRng};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A method a sweep runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    Scanline,
    Vector,
    /// The scanline pipeline's spans drawn by 000's shading engines (`model::se::array`).
    Se,
}

impl Method {
    pub const ALL: [Method; 3] = [Method::Scanline, Method::Vector, Method::Se];

    /// The name the CLI and the rows use.
    pub fn name(self) -> &'static str {
        match self {
            Method::Scanline => "scanline",
            Method::Vector => "vector",
            Method::Se => "se",
        }
    }

    /// Whether knob `knob` is one of this method's.
    pub fn has(self, knob: &str) -> bool {
        let (scanline, vector, se) = match knob {
            "xy.frac" | "z.frac" | "color.frac" | "ooa.frac" => (true, true, true),
            "z_acc.frac" | "c_acc.frac" | "ooa_d.frac" => (true, false, true),
            "K" | "L" => (true, false, false),
            "dz.int" | "dc.int" | "ooa_d.int" | "z_acc.int" | "c_acc.int" => (true, false, false),
            "bary.frac" | "inv_w.frac" | "lanes" => (false, true, false),
            _ => (false, false, false),
        };
        match self {
            Method::Scanline => scanline,
            Method::Vector => vector,
            Method::Se => se,
        }
    }

    /// The parameters of the default design: 001's 7 multipliers and 5 divider stages,
    /// 4 vector lanes.
    pub fn default_params(self) -> BTreeMap<String, u32> {
        let t = model::cycles::Timing::default();
        match self {
            Method::Scanline => BTreeMap::from([("K".into(), t.setup_multipliers), ("L".into(), t.divider_latency)]),
            Method::Vector => BTreeMap::from([("lanes".into(), 4)]),
            Method::Se => BTreeMap::new(),
        }
    }
}

/// Every knob a grid may name.
pub const KNOBS: [&str; 17] = [
    "xy.frac",
    "z.frac",
    "color.frac",
    "inv_w.frac",
    "ooa.frac",
    "ooa_d.frac",
    "z_acc.frac",
    "c_acc.frac",
    "bary.frac",
    "dz.int",
    "dc.int",
    "ooa_d.int",
    "z_acc.int",
    "c_acc.int",
    "K",
    "L",
    "lanes",
];

/// Whether `knob` is a method parameter rather than a format.
fn is_param(knob: &str) -> bool {
    matches!(knob, "K" | "L" | "lanes")
}

/// The joint sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Joint {
    pub samples: u32,
    pub seed: u64,
}

/// A grid: see the module documentation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Grid {
    #[serde(default = "all_methods")]
    pub methods: Vec<Method>,
    #[serde(default)]
    pub sensitivity: BTreeMap<String, Vec<u32>>,
    #[serde(default)]
    pub joint: Option<Joint>,
}

fn all_methods() -> Vec<Method> {
    Method::ALL.to_vec()
}

/// The default grid: every knob from too narrow to wide (at least 30 points per method).
impl Default for Grid {
    fn default() -> Grid {
        let knobs: [(&str, &[u32]); 11] = [
            ("xy.frac", &[2, 3, 4, 5, 6, 7, 8]),
            ("z.frac", &[12, 16, 20, 24, 28, 32]),
            ("color.frac", &[0, 1, 2, 4, 8]),
            ("ooa.frac", &[6, 8, 12, 16, 20, 24, 32]),
            ("z_acc.frac", &[24, 28, 32, 36, 40, 44, 50]),
            ("c_acc.frac", &[8, 12, 16, 20, 24, 30, 38]),
            ("bary.frac", &[10, 14, 18, 22, 26, 30, 36]),
            ("inv_w.frac", &[6, 8, 10, 12, 15, 20]),
            ("K", &[1, 2, 3, 4, 5, 6, 7]),
            ("L", &[1, 3, 5, 8]),
            ("lanes", &[1, 2, 4, 8, 16]),
        ];
        Grid {
            methods: all_methods(),
            sensitivity: knobs.iter().map(|(k, v)| (k.to_string(), v.to_vec())).collect(),
            joint: Some(Joint { samples: 60, seed: 1 }),
        }
    }
}

/// One design point of one method, before a scene gives it a resolution.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Point {
    pub method: Method,
    /// `default`, `<knob>=<value>`, `joint-<i>`.
    pub name: String,
    /// `default`, `sensitivity` or `joint`.
    pub kind: String,
    /// The knobs set, with their values.
    pub set: BTreeMap<String, u32>,
    /// The size class of the design, when not the screen's own (`fx::resolution_bits`):
    /// a workload of several screen sizes drawn by one design, or a class below 10
    /// (`edgepaint fit`). Never below the smallest that holds the screen
    /// (`fx::smallest_class`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub class: Option<u32>,
}

impl Grid {
    /// Reads a grid file's text; the error names the unknown key or knob.
    pub fn parse(text: &str) -> Result<Grid, String> {
        let g: Grid = serde_json::from_str(text).map_err(|e| e.to_string())?;
        if g.methods.is_empty() {
            return Err("\"methods\" is empty: name at least one of scanline, vector, se".into());
        }
        for (knob, values) in &g.sensitivity {
            if !KNOBS.contains(&knob.as_str()) {
                return Err(format!("unknown knob \"{knob}\" (knobs: {})", KNOBS.join(", ")));
            }
            if values.is_empty() {
                return Err(format!("knob \"{knob}\" has no values"));
            }
        }
        Ok(g)
    }

    /// Every design point, method by method: the default, the sensitivity points, the
    /// joint sample.
    pub fn points(&self) -> Vec<Point> {
        let mut out = Vec::new();
        for &method in &self.methods {
            let point = |name: String, kind: &str, set: BTreeMap<String, u32>| Point {
                method,
                name,
                kind: kind.into(),
                set,
                class: None,
            };
            out.push(point("default".into(), "default", BTreeMap::new()));
            let knobs: Vec<(&String, &Vec<u32>)> = self.sensitivity.iter().filter(|(k, _)| method.has(k)).collect();
            for (knob, values) in &knobs {
                for v in *values {
                    out.push(point(format!("{knob}={v}"), "sensitivity", [((*knob).clone(), *v)].into()));
                }
            }
            if let Some(j) = self.joint {
                let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(j.seed ^ method as u64);
                for i in 0..j.samples {
                    let mut set: BTreeMap<String, u32> =
                        knobs.iter().map(|(k, v)| ((*k).clone(), v[rng.gen_range(0..v.len())])).collect();
                    // An accumulator keeps at least its input's fraction bits.
                    for (acc, input) in [("z_acc.frac", "z.frac"), ("c_acc.frac", "color.frac")] {
                        if let (Some(&a), Some(&i)) = (set.get(acc), set.get(input)) {
                            set.insert(acc.into(), a.max(i));
                        }
                    }
                    out.push(point(format!("joint-{i}"), "joint", set));
                }
            }
        }
        out
    }
}

impl Point {
    /// The point's formats and parameters for a `width` x `height` screen; the error names
    /// the point and says why its formats are impossible.
    pub fn resolve(&self, width: u32, height: u32) -> Result<(Formats, BTreeMap<String, u32>), String> {
        let n = self.class(width, height);
        let side = 1u32 << n.min(16);
        // The shading engines' words hold 32 bits at most, which the wide formats exceed.
        let wide = self.kind == "sensitivity" && self.set.keys().all(|k| !is_param(k)) && self.method != Method::Se;
        let mut f = if wide { Formats::wide(side, side) } else { Formats::for_n(n) };
        let mut params = self.method.default_params();
        let mut given = Given::NONE;
        let mut ints = Vec::new();
        for (knob, &v) in &self.set {
            if is_param(knob) {
                params.insert(knob.clone(), v);
                continue;
            }
            if let Some(q) = knob.strip_suffix(".int") {
                ints.push((q, v));
                continue;
            }
            let frac = |fm: Fmt| Fmt { frac: v, ..fm };
            match knob.as_str() {
                "xy.frac" => f.xy = frac(f.xy),
                "z.frac" => f.z = frac(f.z),
                "color.frac" => f.color = frac(f.color),
                "inv_w.frac" => f.inv_w = frac(f.inv_w),
                "ooa.frac" => f.ooa = frac(f.ooa),
                "bary.frac" => f.bary = frac(f.bary),
                "ooa_d.frac" => (f.ooa_d, given.ooa_d) = (frac(f.ooa_d), true),
                "z_acc.frac" => (f.z_acc, f.dz, given.z_acc, given.dz) = (frac(f.z_acc), frac(f.dz), true, true),
                "c_acc.frac" => (f.c_acc, f.dc, given.c_acc, given.dc) = (frac(f.c_acc), frac(f.dc), true, true),
                _ => return Err(format!("point {}: unknown knob \"{knob}\"", self.label())),
            }
        }
        if self.method == Method::Vector && !model::vector::lanes_supported(params["lanes"]) {
            let l = params["lanes"];
            return Err(format!(
                "point {}: lanes = {l}: the vector walk's chunks are aligned to the lanes, so 1, 2, 4, ... up to 64",
                self.label()
            ));
        }
        if wide {
            // The others stay wide; only what the modular condition and the fraction
            // couplings need moves.
            if !given.ooa_d {
                f.ooa_d.frac = f.ooa_d.frac.max(f.dc.frac).max(f.dz.frac.saturating_sub(f.z.frac));
            }
        } else {
            f = f.follow(n, given);
        }
        let (dz, dc, ooa_d) = f.modular_ints();
        (f.dz.int, f.dc.int, f.ooa_d.int) = (f.dz.int.max(dz), f.dc.int.max(dc), f.ooa_d.int.max(ooa_d));
        for (q, v) in ints {
            match q {
                "dz" => f.dz.int = v,
                "dc" => f.dc.int = v,
                "ooa_d" => f.ooa_d.int = v,
                "z_acc" => f.z_acc.int = v,
                "c_acc" => f.c_acc.int = v,
                _ => return Err(format!("point {}: unknown knob \"{q}.int\"", self.label())),
            }
        }
        f.check(width, height).map_err(|e| format!("point {}: {e}", self.label()))?;
        Ok((f, params))
    }

    /// The size class of the point's design on a `width` x `height` screen.
    pub fn class(&self, width: u32, height: u32) -> u32 {
        self.class.map_or(fx::resolution_bits(width, height), |c| c.max(fx::smallest_class(width, height)))
    }

    /// `<method> <name>`, as errors name a point.
    pub fn label(&self) -> String {
        format!("{} {}", self.method.name(), self.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_grid_has_30_points_per_method_all_possible_up_to_class_12() {
        let points = Grid::default().points();
        for m in Method::ALL {
            let n = points.iter().filter(|p| p.method == m).count();
            assert!(n >= 30, "{} has {n} points", m.name());
        }
        for (w, h) in [(64, 48), (320, 240), (1024, 768), (4096, 4096)] {
            for p in &points {
                p.resolve(w, h).unwrap_or_else(|e| panic!("{w}x{h}: {e}"));
            }
        }
    }

    #[test]
    fn a_knob_moves_only_itself_and_what_must_follow() {
        let p = Point {
            method: Method::Scanline,
            name: "xy.frac=8".into(),
            kind: "sensitivity".into(),
            set: [("xy.frac".into(), 8)].into(),
            class: None,
        };
        let (f, _) = p.resolve(320, 240).unwrap();
        let w = Formats::wide(320, 240);
        assert_eq!(f.xy.frac, 8);
        assert_eq!((f.z, f.color, f.ooa, f.z_acc, f.c_acc), (w.z, w.color, w.ooa, w.z_acc, w.c_acc));
        assert_eq!((f.dz, f.dc, f.ooa_d), (w.dz, w.dc, w.ooa_d), "wide enough for 16 subpixel bits, so for 8");
        let joint = Point { kind: "joint".into(), name: "joint-0".into(), ..p };
        let (f, params) = joint.resolve(320, 240).unwrap();
        assert_eq!(f, Formats::with_overrides(320, 240, &serde_json::json!({"xy": "S11.8 half-up"})).unwrap());
        assert_eq!(params, Method::Scanline.default_params());
    }

    /// A point with a class below 10 (`edgepaint fit` of a small screen) is at that class's
    /// defaults, never below the screen's smallest class; `<q>.int` knobs set integer bits
    /// below the modular minimum, and nothing else moves.
    #[test]
    fn a_class_below_10_and_integer_bits_from_ranges() {
        let p = Point {
            method: Method::Scanline,
            name: "fit".into(),
            kind: "joint".into(),
            set: BTreeMap::new(),
            class: Some(8),
        };
        assert_eq!((p.class(320, 240), p.class(200, 150), p.class(20, 10)), (9, 8, 8), "never below class 8");
        assert_eq!(Point { class: None, ..p.clone() }.class(320, 240), 10, "a sweep's points keep class 10");
        let (f, _) = p.resolve(320, 240).unwrap();
        assert_eq!(f, Formats::for_n(9));
        assert_eq!(f.xy, Fmt::s(10, 4).half_up());
        let ints = Point { set: [("dz.int".into(), 2), ("dc.int".into(), 9), ("c_acc.int".into(), 8)].into(), ..p };
        let (g, _) = ints.resolve(200, 150).unwrap();
        let d = Formats::for_n(8);
        assert_eq!((g.dz, g.dc, g.c_acc), (Fmt::s(2, d.dz.frac), Fmt::s(9, d.dc.frac), Fmt::s(8, d.c_acc.frac)));
        assert_eq!((g.ooa_d, g.z_acc, g.xy), (d.ooa_d, d.z_acc, d.xy));
        assert_eq!(g.narrowed(), ["dz", "dc", "c_acc"]);
        let bad = Point { set: [("dz.int".into(), 0)].into(), ..ints };
        assert!(bad.resolve(200, 150).unwrap_err().contains("at least 1 integer bit"));
    }

    #[test]
    fn an_impossible_point_is_an_error_naming_it() {
        let g = Grid::parse(r#"{"methods": ["scanline"], "sensitivity": {"z.frac": [40]}}"#).unwrap();
        let p = &g.points()[1];
        let e = p.resolve(320, 240).unwrap_err();
        assert!(e.contains("scanline z.frac=40") && e.contains("depth buffer"), "{e}");
        let e = Grid::parse(r#"{"sensitivity": {"w.frac": [4]}}"#).unwrap_err();
        assert!(e.contains("unknown knob \"w.frac\""), "{e}");
        assert!(Grid::parse(r#"{"method": ["scanline"]}"#).unwrap_err().contains("unknown field"));
        assert!(Grid::parse(r#"{"methods": []}"#).unwrap_err().contains("\"methods\" is empty"));
        let g = Grid::parse(r#"{"methods": ["vector"], "sensitivity": {"lanes": [3]}}"#).unwrap();
        let e = g.points()[1].resolve(320, 240).unwrap_err();
        assert!(e.contains("vector lanes=3") && e.contains("lanes = 3"), "{e}");
    }
}
