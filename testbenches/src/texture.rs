//! The pins the texture units' testbenches share: a pixel's texture coordinates and their
//! gradients, the inputs of `rtl::texture_coords` and of `rtl::texture_unit`, which hands
//! them on to it (paper 001 section II-5, eq. (3) and (4)).

use crate::Value;
use model::texture_unit::{TexGrad, TexIn};
use rtl::texture_coords::{DQ, DST, QB, ST};

/// `v`'s low `bits` bits, as a port value.
fn raw(bits: usize, v: i64) -> Value {
    Value::new(bits, (v as u128) & ((1u128 << bits) - 1))
}

/// The pixel's s·q, t·q and q (`inp_sq`, `inp_tq`, `inp_q`) and the triangle's gradients of
/// them (`inp_dsq_x`, ..., `inp_dq_y`), raw, on the pins of `rtl::texture_coords` and
/// `rtl::texture_unit`.
pub fn coord_pins(p: &TexIn, g: &TexGrad) -> [(&'static str, Value); 9] {
    [
        ("inp_sq", raw(ST, p.sq)),
        ("inp_tq", raw(ST, p.tq)),
        ("inp_q", raw(QB, p.q)),
        ("inp_dsq_x", raw(DST, g.dsq[0])),
        ("inp_dsq_y", raw(DST, g.dsq[1])),
        ("inp_dtq_x", raw(DST, g.dtq[0])),
        ("inp_dtq_y", raw(DST, g.dtq[1])),
        ("inp_dq_x", raw(DQ, g.dq[0])),
        ("inp_dq_y", raw(DQ, g.dq[1])),
    ]
}
