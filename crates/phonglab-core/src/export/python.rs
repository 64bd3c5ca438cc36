//! Python literals for the generated notebooks and programs.

use glam::{DMat4, DVec4};

/// A number as Python reads it back exactly: `1`, `0.2125`, `1e-05`, `-665.108`; whole
/// numbers without a point, as the worksheet writes them. Not-finite numbers become
/// `float('inf')` / `float('nan')`.
pub fn num(x: f64) -> String {
    if x.is_nan() {
        return "float('nan')".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "float('inf')".into() } else { "-float('inf')".into() };
    }
    if x == x.trunc() && x.abs() < 1e15 {
        // -0 is written 0: Python's int has no negative zero, and no term depends on it.
        return format!("{}", x as i64);
    }
    // Rust's shortest round-trip forms: as a decimal while that is short (`0.00001`, as the
    // worksheet writes), else with an exponent (`1e-20`, which Python reads too).
    let decimal = format!("{x}");
    if decimal.len() <= 12 { decimal } else { format!("{x:?}") }
}

/// `np.array([x, y, z, w])`.
pub fn array4(v: DVec4) -> String {
    format!("np.array([{}, {}, {}, {}])", num(v.x), num(v.y), num(v.z), num(v.w))
}

/// A colour as the worksheet writes it: `np.array([r, g, b, 0])` (the fourth component
/// unused; alpha is kept apart).
pub fn colour(c: DVec4) -> String {
    array4(DVec4::new(c.x, c.y, c.z, 0.0))
}

/// A matrix as the worksheet writes its `mview`: rows as tuples.
pub fn matrix(m: &DMat4) -> String {
    let rows = crate::model::transform::mat4_rows(m);
    let row = |r: &[f64; 4]| format!("({}, {}, {}, {})", num(r[0]), num(r[1]), num(r[2]), num(r[3]));
    format!("np.array([{}])", rows.iter().map(row).collect::<Vec<_>>().join(", "))
}

/// The shininess as the worksheet writes it when it is a fraction of 128 (`0.2*128`, the
/// classic material tables' form), else the number.
pub fn shininess(s: f64) -> String {
    let f = s / 128.0;
    // Multiplying by 128 is exact, so `f*128` reads back as `s` exactly.
    let short = num(f);
    if f * 128.0 == s && s != 0.0 && short.len() <= 8 && s != s.trunc() { format!("{short}*128") } else { num(s) }
}

/// A Python string literal whose value is `s`, on one line ([`crate::formats::escape::python::string`]).
pub fn string(s: &str) -> String {
    crate::formats::escape::python::string(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_exactly() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-665.108), "-665.108");
        assert_eq!(num(0.00001), "0.00001");
        assert_eq!(num(1e-20), "1e-20");
        assert_eq!(num(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(shininess(25.6), "0.2*128");
        assert_eq!(shininess(51.2), "0.4*128");
        assert_eq!(shininess(100.0), "100");
        assert_eq!(shininess(0.0), "0");
        assert_eq!(colour(DVec4::new(0.2125, 0.1275, 0.054, 1.0)), "np.array([0.2125, 0.1275, 0.054, 0])");
    }
}
