//! The model's transactions as port values, and back: a set-up triangle
//! (`model::triangle_setup::TriangleSetupOut`), a span command (`model::edge_walk::SpanCmd`) and a
//! pixel (`model::span::Pixel`), each flattened into ports `<prefix>_<field>` with nested
//! fields joined by `_`, as the RTL names them (`inp_maj_at_c0`, `out_left_z`); the links
//! declared in `rtl::links` as `<end>$<field>` (`out$rgb2`), their fields and widths read off
//! the declaration.
//! Widths come from `rtl::widths`, so a value that does not fit its port fails here.

use crate::{Outputs, Value};
use model::edge_walk::SpanCmd;
use model::span::Pixel;
use model::triangle_setup::{Attrs, Edge, TriangleSetupOut, Walk};
use rtl::link::Link;
use rtl::links::{PixelSink, SpanCmdSink};
use rtl::widths::{C_ACC, DC, DZ, EDGE_D, EDGE_Q, PIXEL, Z_ACC};

/// Named port values, ready for `Dual::cycle` (through [`as_pins`]).
pub type PinValues = Vec<(String, Value)>;

/// `v` as a `width`-bit port value: two's complement when negative. Panics unless `v` fits
/// `width` bits as a signed or an unsigned number.
pub fn raw(width: usize, v: i128) -> Value {
    assert!(v >= -(1i128 << (width - 1)) && v < (1i128 << width), "{v} does not fit a {width}-bit port");
    Value::new(width, (v as u128) & (u128::MAX >> (128 - width)))
}

/// A port value read as a two's complement number.
pub fn signed(v: &Value) -> i128 {
    let w = v.width();
    fx::wrap_s(v.to_u128() as i128, w as u32)
}

/// A port value read as an unsigned number.
pub fn unsigned(v: &Value) -> u128 {
    v.to_u128()
}

/// Borrows named values as `Dual::cycle` takes them.
pub fn as_pins(values: &[(String, Value)]) -> Vec<(&str, Value)> {
    values.iter().map(|(n, v)| (n.as_str(), v.clone())).collect()
}

fn attrs(out: &mut PinValues, name: &str, a: &Attrs, zw: usize, cw: usize) {
    out.push((format!("{name}_z"), raw(zw, a.z)));
    for (i, c) in a.c.iter().enumerate() {
        out.push((format!("{name}_c{i}"), raw(cw, *c)));
    }
}

/// A set-up triangle on ports `<prefix>_*` (`edge_walk`'s `inp_*`).
pub fn triangle_setup_out(prefix: &str, s: &TriangleSetupOut) -> PinValues {
    let mut out = vec![
        (format!("{prefix}_walk"), Value::new(1, (s.walk == Walk::Up) as u128)),
        (format!("{prefix}_maj_left"), Value::new(1, s.maj_left as u128)),
    ];
    let edges: [(&str, &Edge); 3] = [("maj", &s.maj), ("short0", &s.short[0]), ("short1", &s.short[1])];
    for (name, e) in edges {
        let p = format!("{prefix}_{name}");
        out.push((format!("{p}_j"), raw(PIXEL, e.j as i128)));
        out.push((format!("{p}_count"), raw(PIXEL, e.count as i128)));
        out.push((format!("{p}_x"), raw(PIXEL, e.x)));
        out.push((format!("{p}_r"), raw(EDGE_D, e.r)));
        out.push((format!("{p}_q"), raw(EDGE_Q, e.q)));
        out.push((format!("{p}_rho"), raw(EDGE_D, e.rho)));
        out.push((format!("{p}_d"), raw(EDGE_D, e.d)));
        attrs(&mut out, &format!("{p}_at"), &e.at, Z_ACC, C_ACC);
        attrs(&mut out, &format!("{p}_inc0"), &e.inc0, DZ, DC);
        attrs(&mut out, &format!("{p}_inc1"), &e.inc1, DZ, DC);
    }
    attrs(&mut out, &format!("{prefix}_ddx"), &s.ddx, DZ, DC);
    out
}

/// Field `field` of attributes `a`: `z`, `c0`, `c1` or `c2`.
fn attr(a: &Attrs, field: &str) -> i128 {
    match field {
        "z" => a.z,
        "c0" => a.c[0],
        "c1" => a.c[1],
        "c2" => a.c[2],
        _ => panic!("model::triangle_setup::Attrs has no field {field}"),
    }
}

/// A span command on the pins of link end `end` (`span`'s `inp`: `links::SpanCmdSink`).
pub fn span_cmd(end: &str, c: &SpanCmd) -> PinValues {
    link_pins::<SpanCmdSink>(end, |field| match field.split_once('_') {
        None if field == "y" => c.y as i128,
        None if field == "xl" => c.xl,
        None if field == "xr" => c.xr,
        Some(("left", f)) => attr(&c.left, f),
        Some(("right", f)) => attr(&c.right, f),
        Some(("ddx", f)) => attr(&c.ddx, f),
        _ => panic!("model::edge_walk::SpanCmd has no field {field}"),
    })
}

fn attrs_of(o: &Outputs, name: &str) -> Attrs {
    Attrs { z: signed(o.get(&format!("{name}_z"))), c: std::array::from_fn(|i| signed(o.get(&format!("{name}_c{i}")))) }
}

/// The span command on the pins of link end `end` (`edge_walk`'s `out`: `links::SpanCmdSource`).
pub fn span_cmd_of(o: &Outputs, end: &str) -> SpanCmd {
    SpanCmd {
        y: unsigned(o.get(&format!("{end}$y"))) as i32,
        xl: signed(o.get(&format!("{end}$xl"))),
        xr: signed(o.get(&format!("{end}$xr"))),
        left: attrs_of(o, &format!("{end}$left")),
        right: attrs_of(o, &format!("{end}$right")),
        ddx: attrs_of(o, &format!("{end}$ddx")),
    }
}

/// The values of a link's fields on end `end` of a unit (pins `<end>$<field>`, each at the
/// link's width), `value` giving each field's value by name.
fn link_pins<L: Link>(end: &str, value: impl Fn(&str) -> i128) -> PinValues {
    L::FIELDS.iter().zip(L::WIDTHS).map(|(f, w)| (format!("{end}${f}"), raw(*w, value(f)))).collect()
}

/// A pixel on the pins of link end `end` (`pixel_out`'s `inp`: `links::PixelSink`).
pub fn pixel(end: &str, p: &Pixel) -> PinValues {
    link_pins::<PixelSink>(end, |field| match field {
        "x" => p.x as i128,
        "y" => p.y as i128,
        "z" => p.z as i128,
        "rgb0" => p.rgb[0] as i128,
        "rgb1" => p.rgb[1] as i128,
        "rgb2" => p.rgb[2] as i128,
        _ => panic!("model::span::Pixel has no field {field}"),
    })
}

/// The pixel on the pins of link end `end` (`span`'s `out`: `links::PixelSource`).
pub fn pixel_of(o: &Outputs, end: &str) -> Pixel {
    let get = |field: &str| unsigned(o.get(&format!("{end}${field}")));
    Pixel {
        x: get("x") as u32,
        y: get("y") as u32,
        z: get("z") as u32,
        rgb: std::array::from_fn(|i| get(&format!("rgb{i}")) as u8),
    }
}
