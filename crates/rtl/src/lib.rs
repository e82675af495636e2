//! edgepaint hardware units in rust-hdl.
