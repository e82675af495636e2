//! Stepping rust-hdl units directly, and their pins by name.
//!
//! rust-hdl's threaded `Simulation` ran at 8–25k cycles/s here; stepping a unit with
//! [`simulate`] runs it at full speed. [`settle`] propagates combinational logic, [`tick`]
//! is one clock. [`Pins`] names a unit's top-level ports as they appear in the emitted
//! Verilog and moves their values as [`Value`]s (any width), so one test bench can drive
//! the unit here and, through the same names, its Verilog under Verilator.

use rust_hdl::prelude::*;
use std::fmt;

/// How many delta cycles a unit may take to settle before we call it a loop.
/// The deepest unit so far, the EPT at P = 1024, needs up to 39 (one per level down the tree
/// and one per level back up, as each subtree's mask joins its parent's).
const SETTLE_LIMIT: usize = 256;

/// Propagates the inputs through the combinational logic.
/// Panics if the unit does not settle (a combinational loop).
pub fn settle<U: Block>(u: &mut U) {
    assert!(simulate(u, SETTLE_LIMIT), "the unit did not settle in {SETTLE_LIMIT} delta cycles");
}

/// One clock of direct stepping: settle the inputs, rising edge, falling edge.
pub fn tick<U: Block>(u: &mut U, clk: fn(&mut U) -> &mut Signal<In, Clock>) {
    settle(u);
    clk(u).next = true.into();
    settle(u);
    clk(u).next = false.into();
    settle(u);
}

/// Direction of a top-level port.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PortDir {
    In,
    Out,
}

impl PortDir {
    /// `input` or `output`, as in Verilog and `hdl-out/manifest.json`.
    pub fn verilog(self) -> &'static str {
        match self {
            PortDir::In => "input",
            PortDir::Out => "output",
        }
    }
}

/// A unit's top-level ports by their Verilog names.
pub trait Pins {
    /// Drives input `pin` (its `next`); panics on an unknown name.
    fn set(&mut self, pin: &str, value: &Value);
    /// Reads output `pin`; panics on an unknown name.
    fn get(&self, pin: &str) -> Value;
    /// The clock input, for clocked units.
    fn clock(&mut self) -> Option<&mut Signal<In, Clock>> {
        None
    }
}

/// A port's value type, moved to and from a [`Value`]: `Bit` and `Bits<N>`.
pub trait PinValue: Sized {
    fn from_value(v: &Value) -> Self;
    fn to_value(&self) -> Value;
}

impl PinValue for bool {
    fn from_value(v: &Value) -> Self {
        assert_eq!(v.width(), 1, "a {}-bit value for a 1-bit port", v.width());
        v.bit(0)
    }
    fn to_value(&self) -> Value {
        Value::new(1, *self as u128)
    }
}

impl<const N: usize> PinValue for Bits<N> {
    fn from_value(v: &Value) -> Self {
        v.to_bits()
    }
    fn to_value(&self) -> Value {
        Value::from_bits(*self)
    }
}

/// Implements [`Pins`] for a clocked unit from its port fields: every input but the clock,
/// then every output, each named as in the Verilog, and the ends of links it holds
/// (`links: [inp, out]`: pins `<end>$<field>`, through `crate::link::LinkPins`). The
/// dual-simulation harness drives and reads every port by name, so a port left out of the
/// lists fails the unit's tests.
#[macro_export]
macro_rules! pins {
    // A unit with generic parameters: `pins!(impl[const N: usize] Unit<N> { ... })`.
    (impl[$($g:tt)*] $unit:ty {
        clock: $clock:ident,
        inputs: [$($i:ident),* $(,)?],
        outputs: [$($o:ident),* $(,)?]
        $(, links: [$($l:ident),* $(,)?])? $(,)?
    }) => {
        impl<$($g)*> $crate::sim::Pins for $unit {
            fn set(&mut self, pin: &str, value: &$crate::sim::Value) {
                match pin {
                    $(stringify!($i) => self.$i.next = $crate::sim::PinValue::from_value(value),)*
                    _ => {
                        $($(if let Some(field) = pin.strip_prefix(concat!(stringify!($l), "$")) {
                            if $crate::link::LinkPins::set(&mut self.$l, field, value) {
                                return;
                            }
                        })*)?
                        panic!("{} has no input pin {pin}", stringify!($unit));
                    }
                }
            }
            fn get(&self, pin: &str) -> $crate::sim::Value {
                match pin {
                    $(stringify!($o) => $crate::sim::PinValue::to_value(&self.$o.val()),)*
                    _ => {
                        $($(if let Some(field) = pin.strip_prefix(concat!(stringify!($l), "$")) {
                            if let Some(v) = $crate::link::LinkPins::get(&self.$l, field) {
                                return v;
                            }
                        })*)?
                        panic!("{} has no output pin {pin}", stringify!($unit));
                    }
                }
            }
            fn clock(&mut self) -> Option<&mut rust_hdl::prelude::Signal<rust_hdl::prelude::In, rust_hdl::prelude::Clock>> {
                Some(&mut self.$clock)
            }
        }
    };
    ($unit:ty { $($body:tt)* }) => {
        $crate::pins!(impl[] $unit { $($body)* });
    };
}

/// A value on a port of any width: bit i is bit i % 64 of word i / 64; bits at and
/// above `width` are zero.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Value {
    width: usize,
    words: Vec<u64>,
}

impl Value {
    /// All zeros.
    pub fn zero(width: usize) -> Self {
        Value { width, words: vec![0; width.div_ceil(64).max(1)] }
    }

    /// `v` as a `width`-bit value; panics if it does not fit.
    pub fn new(width: usize, v: u128) -> Self {
        assert!(width >= 128 || v >> width == 0, "{v:#x} does not fit in {width} bits");
        let mut out = Self::zero(width);
        out.words[0] = v as u64;
        if out.words.len() > 1 {
            out.words[1] = (v >> 64) as u64;
        }
        out
    }

    /// From little-endian 64-bit words; bits above `width` are cleared.
    pub fn from_words(width: usize, words: &[u64]) -> Self {
        let mut out = Self::zero(width);
        for (o, w) in out.words.iter_mut().zip(words) {
            *o = *w;
        }
        out.clear_above_width();
        out
    }

    /// From booleans, element i = bit i.
    pub fn from_bools(bits: &[bool]) -> Self {
        let mut out = Self::zero(bits.len());
        for (i, _) in bits.iter().enumerate().filter(|(_, b)| **b) {
            out.words[i / 64] |= 1 << (i % 64);
        }
        out
    }

    /// Width in bits.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Little-endian 64-bit words, `width.div_ceil(64)` of them (one for width 0).
    pub fn words(&self) -> &[u64] {
        &self.words
    }

    /// Bit i.
    pub fn bit(&self, i: usize) -> bool {
        assert!(i < self.width, "bit {i} of a {}-bit value", self.width);
        (self.words[i / 64] >> (i % 64)) & 1 == 1
    }

    /// The value as a u128; panics if wider than 128 bits.
    pub fn to_u128(&self) -> u128 {
        assert!(self.width <= 128, "a {}-bit value does not fit in u128", self.width);
        self.words[0] as u128 | self.words.get(1).map_or(0, |w| (*w as u128) << 64)
    }

    /// As a rust-hdl bit vector; panics if the widths differ.
    pub fn to_bits<const N: usize>(&self) -> Bits<N> {
        assert_eq!(self.width, N, "a {}-bit value for a {N}-bit port", self.width);
        if N <= 64 {
            return Bits::from(self.words[0]);
        }
        self.words.iter().rev().fold(Bits::default(), |acc, w| (acc << 64) | Bits::from(*w))
    }

    /// From a rust-hdl bit vector.
    pub fn from_bits<const N: usize>(b: Bits<N>) -> Self {
        if N <= 64 {
            return Self::new(N, b.to_u64() as u128);
        }
        let words: Vec<u64> = (0..N.div_ceil(64)).map(|i| (b >> (64 * i) as u64).get_bits::<64>(0).to_u64()).collect();
        Self::from_words(N, &words)
    }

    fn clear_above_width(&mut self) {
        let tail = self.width % 64;
        if tail != 0 {
            let last = self.words.len() - 1;
            self.words[last] &= (1u64 << tail) - 1;
        }
    }
}

/// Verilog-style: `6'h2a`, `1024'h0000…`, digits grouped by 4 with `_` past 16 digits.
impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let digits = self.width.div_ceil(4).max(1);
        let hex: String = (0..digits)
            .rev()
            .map(|d| {
                let nibble = (self.words[d * 4 / 64] >> (d * 4 % 64)) & 0xf;
                char::from_digit(nibble as u32, 16).expect("a nibble is one hex digit")
            })
            .collect();
        let grouped = if digits > 16 {
            hex.as_bytes()
                .rchunks(4)
                .rev()
                .map(|c| std::str::from_utf8(c).expect("hex is ASCII"))
                .collect::<Vec<_>>()
                .join("_")
        } else {
            hex
        };
        write!(f, "{}'h{}", self.width, grouped)
    }
}

impl fmt::Debug for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}
