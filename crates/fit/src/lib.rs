//! `edgepaint fit`: model no more than a workload needs. [`target::Target`] is the accuracy
//! a user asks for (`--target SPEC`); [`search::fit`] finds the narrowest formats of the
//! scanline pipeline with which every scene of the workload meets it, by the bit-exact
//! models against the float reference, then setup's parameters for an objective;
//! [`parts::needed`] leaves out the optional parts (clipping, culling, the depth test) the
//! workload never uses; [`method`] sets the scanline design beside the barycentric and SE
//! back ends at their built formats and chooses the method (`--method auto`); [`texture`]
//! fits the texture unit (001 section II-5): whether the workload needs it, its filter and
//! its mip chain, and its narrowest precision knobs.

pub mod method;
pub mod parts;
pub mod search;
pub mod target;
pub mod texture;
