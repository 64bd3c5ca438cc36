//! The 24 classic OpenGL materials (the SGI Red Book "teapots" table), from `assets/`.

use std::sync::OnceLock;

use glam::DVec4;

use crate::model::scene::Material;

/// The table as shipped in `assets/materials-classic.csv` (compiled in; the core reads no files).
pub const CLASSIC_CSV: &str = include_str!("../../../../assets/materials-classic.csv");

/// A named material of the classic table.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedMaterial {
    /// e.g. "bronze".
    pub name: String,
    /// GL material; shininess = the table's fraction * 128; emission 0; alpha 1.
    pub material: Material,
}

/// Parses the classic CSV format: `name, ambient rgb, diffuse rgb, specular rgb, shininess fraction`,
/// `#` comments and a header line.
pub fn parse_classic(csv: &str) -> Result<Vec<NamedMaterial>, String> {
    let mut out = Vec::new();
    for (lineno, line) in csv.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') || line.starts_with("name,") {
            continue;
        }
        let cols: Vec<&str> = line.split(',').map(str::trim).collect();
        if cols.len() != 11 {
            return Err(format!("line {}: expected 11 columns, found {}", lineno + 1, cols.len()));
        }
        let mut v = [0.0; 10];
        for (i, c) in cols[1..].iter().enumerate() {
            v[i] = c.parse().map_err(|_| format!("line {}: column {} is not a number: {c:?}", lineno + 1, i + 2))?;
        }
        let c = |i: usize| DVec4::new(v[i], v[i + 1], v[i + 2], 1.0);
        out.push(NamedMaterial {
            name: cols[0].to_string(),
            material: Material {
                ambient: c(0),
                diffuse: c(3),
                specular: c(6),
                emission: DVec4::new(0.0, 0.0, 0.0, 1.0),
                shininess: v[9] * 128.0,
            },
        });
    }
    Ok(out)
}

/// The 24 classic materials, in table order.
pub fn classic() -> &'static [NamedMaterial] {
    static TABLE: OnceLock<Vec<NamedMaterial>> = OnceLock::new();
    TABLE.get_or_init(|| parse_classic(CLASSIC_CSV).expect("the shipped material table parses (checked by a test)"))
}

/// A classic material by name (case-insensitive).
pub fn by_name(name: &str) -> Option<&'static Material> {
    classic().iter().find(|m| m.name.eq_ignore_ascii_case(name)).map(|m| &m.material)
}

/// A classic material's name for people, in the current language ("gold" is "ouro" in
/// Portuguese); the scene files keep the table's own names.
pub fn display_name(name: &str) -> String {
    let id = format!("material-name-{}", name.replace('_', "-"));
    if crate::locale::has_message(crate::locale::current().lang, &id) {
        crate::locale::tr(&id)
    } else {
        name.to_string()
    }
}

/// The name of the classic material equal to `m`, if any.
pub fn name_of(m: &Material) -> Option<&'static str> {
    classic().iter().find(|c| &c.material == m).map(|c| c.name.as_str())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_has_24_materials_and_bronze_matches_the_worksheet() {
        assert_eq!(classic().len(), 24);
        let b = by_name("Bronze").unwrap();
        assert_eq!(b.ambient, DVec4::new(0.2125, 0.1275, 0.054, 1.0));
        assert_eq!(b.specular, DVec4::new(0.393548, 0.271906, 0.166721, 1.0));
        assert!((b.shininess - 25.6).abs() < 1e-12);
        assert_eq!(name_of(b), Some("bronze"));
        let g = by_name("gold").unwrap();
        assert!((g.shininess - 51.2).abs() < 1e-12);
    }

    #[test]
    fn malformed_rows_are_reported_with_their_line() {
        let e = parse_classic("name,x\nfoo,1,2\n").unwrap_err();
        assert!(e.contains("line 2"), "{e}");
        let e = parse_classic("foo,1,2,3,4,5,6,7,8,nine,10\n").unwrap_err();
        assert!(e.contains("column 10"), "{e}");
    }
}
