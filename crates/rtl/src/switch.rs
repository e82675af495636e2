//! The optional parts of the scanline pipeline, switched on or off when a unit is built:
//! the reject and cull logic of `cull_sort`, the Y clipping of `edge_walk`, the X and Z
//! clipping of `span` and the depth test of `pixel_out` (papers 003 Fig. 4-6 and 001).
//! Each is present by default; `edgepaint fit` switches off what a workload never uses
//! (README, "Fit"), and the units' parameters `CULL`, `CLIP_Y`, `CLIP_X`, `CLIP_Z` and
//! `DEPTH_TEST` say which.
//!
//! A unit without a part computes what its model computes on every input that does not
//! need that part (no triangle culled or rejected, none crossing the screen's edges or the
//! depth range, no two fragments on one pixel) and is undefined on others: the fit proves
//! its design on the workload in Verilator.

use crate::Params;
use rust_hdl::prelude::*;
use serde::Serialize;

/// A constant bit a unit's kernel tests (`if self.clip_y.on.val() { ... }`): emitted as a
/// `localparam`, so that synthesis removes the logic behind a switch that is off.
#[derive(LogicBlock)]
pub struct Switch {
    pub on: Signal<Out, Bit>,
    value: Constant<Bit>,
}

impl Switch {
    pub fn new(on: bool) -> Switch {
        Switch { on: Default::default(), value: Constant::new(on) }
    }
}

/// Present.
impl Default for Switch {
    fn default() -> Self {
        Switch::new(true)
    }
}

impl Logic for Switch {
    #[hdl_gen]
    fn update(&mut self) {
        self.on.next = self.value.val();
    }
}

/// Which optional parts a build of the scanline pipeline has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Parts {
    /// `cull_sort` rejects triangles wholly outside one clip plane or of zero area, and
    /// culls back faces (`cull_back`); without it every triangle passes, sorted.
    pub cull: bool,
    /// `edge_walk`'s Y clipping: stops at the screen's top and bottom rows, walks up from
    /// vMax when a triangle crosses only the top.
    pub clip_y: bool,
    /// `span`'s X clipping: drops spans off either side, walks right to left from xr when
    /// xl < 0, stops at the last column.
    pub clip_x: bool,
    /// `span`'s Z clipping: drops spans and pixels whose depth leaves [0, z_max].
    pub clip_z: bool,
    /// `pixel_out`'s depth test (LESS); without it every fragment is written.
    pub depth_test: bool,
}

impl Parts {
    /// Every part present: the default design.
    pub const ALL: Parts = Parts { cull: true, clip_y: true, clip_x: true, clip_z: true, depth_test: true };

    /// The parameters and what each means, as `UNITS` lists them.
    pub const PARAMS: [(&'static str, &'static str); 5] = [
        ("CULL", "1: cull_sort rejects and culls (outside a plane, zero area, back faces); 0: every triangle passes"),
        ("CLIP_Y", "1: edge_walk clips to the screen's rows (003 Fig. 5); 0: no triangle crosses the top or bottom"),
        ("CLIP_X", "1: span clips to the screen's columns (003 Fig. 6); 0: no span leaves the screen"),
        ("CLIP_Z", "1: span clips depth to [0, z_max] (003 Fig. 6); 0: no depth leaves it"),
        ("DEPTH_TEST", "1: pixel_out tests depth (LESS); 0: every fragment is written (no two on one pixel)"),
    ];

    /// The parts `params` name (absent ones present); an error for a value other than 0 or 1.
    pub fn of(params: &Params) -> Result<Parts, String> {
        let on = |name: &str| match params.get(name).copied().unwrap_or(1) {
            0 => Ok(false),
            1 => Ok(true),
            v => Err(format!("{name} = {v}: 1 (present) or 0 (absent)")),
        };
        Ok(Parts {
            cull: on("CULL")?,
            clip_y: on("CLIP_Y")?,
            clip_x: on("CLIP_X")?,
            clip_z: on("CLIP_Z")?,
            depth_test: on("DEPTH_TEST")?,
        })
    }

    /// As parameters, in [`Parts::PARAMS`]' order.
    pub fn params(&self) -> [(&'static str, u64); 5] {
        let p = [self.cull, self.clip_y, self.clip_x, self.clip_z, self.depth_test];
        std::array::from_fn(|i| (Parts::PARAMS[i].0, p[i] as u64))
    }
}
