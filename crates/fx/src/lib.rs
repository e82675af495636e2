//! Explicit fixed-point number formats shared by the models and the RTL.
