//! Bit-exact fixed-point models of edgepaint's hardware units. Each module
//! mirrors one RTL unit of the same name in `crates/rtl`.
