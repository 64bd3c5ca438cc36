//! Welding a triangle soup as it is read: `v` lines that are the same number bytes for bytes
//! (a soup, as STL conversions write, repeats each corner once for every triangle that
//! meets it) become one vertex, so a soup costs what the shared mesh of the same surface
//! costs, and its computed normals are the shared mesh's (smooth where the surface is).
//!
//! Only for files that look like soups ([`Welder::wanted`]): a shared mesh has no repeats
//! to find, and its hash map would cost memory for nothing.

use std::collections::HashMap;

use glam::DVec3;

/// From each `v` line to the first `v` line with the same coordinates (bit for bit: `-0`
/// and `0` stay apart, and nothing close is merged).
#[derive(Debug, Default)]
pub struct Welder {
    first: HashMap<[u64; 3], u32>,
    /// Per `v` line, the index of its position among the distinct ones.
    distinct_of: Vec<u32>,
}

impl Welder {
    /// Worth welding: more `v` lines than triangles, which no mesh that shares its corners
    /// has (a closed shared mesh has about one vertex for two triangles; a soup three
    /// for one).
    pub fn wanted(v_lines: usize, triangles: usize) -> bool {
        v_lines > triangles
    }

    /// The most bytes welding `v_lines` lines may take at its peak: the map grown to every
    /// line distinct (a power of two of buckets at 7/8 full, 32 bytes and a control byte
    /// each), the old table beside the new while it grows, and the index per line.
    pub fn peak_bytes(v_lines: u64) -> u64 {
        let buckets = (v_lines * 8 / 7 + 1).next_power_of_two();
        buckets * 33 * 3 / 2 + v_lines * 4
    }

    /// Line `position`'s distinct index, `push`ing it among the distinct ones the first
    /// time its coordinates are met.
    pub fn add(&mut self, position: DVec3, push: impl FnOnce(DVec3) -> u32) -> u32 {
        let key = position.to_array().map(f64::to_bits);
        let id = *self.first.entry(key).or_insert_with(|| push(position));
        self.distinct_of.push(id);
        id
    }

    /// The `v` lines read so far.
    pub fn lines(&self) -> usize {
        self.distinct_of.len()
    }

    /// Line `v`'s distinct index.
    pub fn distinct(&self, v: usize) -> usize {
        self.distinct_of[v] as usize
    }

    /// Frees the map (the per-line indices stay, for the faces still to come).
    pub fn done_with_vertices(&mut self) {
        self.first = HashMap::new();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_bytes_are_one_vertex_and_nothing_else_is() {
        let mut w = Welder::default();
        let mut distinct = Vec::new();
        let mut push = |p: DVec3| {
            distinct.push(p);
            (distinct.len() - 1) as u32
        };
        let a = w.add(DVec3::new(1.0, 2.0, 3.0), &mut push);
        let b = w.add(DVec3::new(1.0, 2.0, 3.0 + f64::EPSILON * 4.0), &mut push);
        let c = w.add(DVec3::new(1.0, 2.0, 3.0), &mut push);
        let d = w.add(DVec3::new(-0.0, 2.0, 3.0), &mut push);
        let e = w.add(DVec3::new(0.0, 2.0, 3.0), &mut push);
        assert_eq!((a, b, c, d, e), (0, 1, 0, 2, 3));
        assert_eq!((w.lines(), w.distinct(2), w.distinct(4)), (5, 0, 3));
        assert_eq!(distinct.len(), 4);
    }

    #[test]
    fn only_a_file_with_more_vertices_than_triangles_is_welded() {
        assert!(Welder::wanted(6, 2));
        assert!(!Welder::wanted(1_000, 2_000));
    }
}
