//! Unit tests of the SFC checks and lowering.
