//! Transcendental functions from the pure-Rust `libm`, so a result is bit-for-bit the same
//! natively and in wasm (the platforms' own maths libraries differ in the last bit).

/// Natural logarithm.
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}
/// Base-10 logarithm.
pub fn log10(x: f64) -> f64 {
    libm::log10(x)
}
/// e to the power x.
pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}
/// Sine.
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}
/// Cosine.
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}
/// Tangent.
pub fn tan(x: f64) -> f64 {
    libm::tan(x)
}
/// Arc sine.
pub fn asin(x: f64) -> f64 {
    libm::asin(x)
}
/// Arc cosine.
pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}
/// Arc tangent.
pub fn atan(x: f64) -> f64 {
    libm::atan(x)
}
/// x to the power y.
pub fn pow(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}
/// Square root (IEEE-exact everywhere; here for uniformity).
pub fn sqrt(x: f64) -> f64 {
    libm::sqrt(x)
}
