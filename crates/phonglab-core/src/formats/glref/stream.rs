//! The case file's outer shape read with serde, element by element: each element is
//! deserialized as `T` (a `Value` to use it, `IgnoredAny` to read past it) and handed on,
//! so only one is in memory at once.

use std::cell::Cell;
use std::fmt;
use std::marker::PhantomData;

use serde::de::{self, DeserializeOwned, DeserializeSeed, IgnoredAny, MapAccess, SeqAccess, Visitor};

use super::FileError;

/// What each case goes to, with its index.
type Each<'a, T> = &'a mut dyn FnMut(T, usize);

/// A reader that counts the bytes read from it (serde_json reads its input byte by byte,
/// so over a buffered reader the count is where the parser is).
pub struct Counted<R> {
    /// The reader counted.
    pub inner: R,
    /// The bytes read so far.
    pub read: std::rc::Rc<Cell<u64>>,
}

impl<R: std::io::Read> std::io::Read for Counted<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.read.set(self.read.get() + n as u64);
        Ok(n)
    }
}

/// A JSON value read past without building it, refused where building it would be
/// (serde_json's nesting limit of 128 included, which its `IgnoredAny` does not check):
/// so a file whose first pass passes is one whose second reads whole.
pub struct Skip;

impl<'de> de::Deserialize<'de> for Skip {
    fn deserialize<D: de::Deserializer<'de>>(d: D) -> Result<Skip, D::Error> {
        d.deserialize_any(Skip)
    }
}

impl<'de> Visitor<'de> for Skip {
    type Value = Skip;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<Skip, E> {
        Ok(Skip)
    }
    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Skip, E> {
        Ok(Skip)
    }
    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Skip, E> {
        Ok(Skip)
    }
    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Skip, E> {
        Ok(Skip)
    }
    fn visit_str<E: de::Error>(self, _: &str) -> Result<Skip, E> {
        Ok(Skip)
    }
    fn visit_unit<E: de::Error>(self) -> Result<Skip, E> {
        Ok(Skip)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Skip, A::Error> {
        while seq.next_element::<Skip>()?.is_some() {}
        Ok(Skip)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Skip, A::Error> {
        while map.next_key::<IgnoredAny>()?.is_some() {
            map.next_value::<Skip>()?;
        }
        Ok(Skip)
    }
}

/// Reads the file's cases into `each`; the count, or why the file is not a case file.
/// `reader` is read a byte at a time: buffer it (`BufReader`).
pub fn cases<R: std::io::Read, T: DeserializeOwned>(reader: R, each: Each<'_, T>) -> Result<usize, FileError> {
    let shape = Cell::new(None);
    let mut de = serde_json::Deserializer::from_reader(reader);
    let r = File { each, shape: &shape, case: PhantomData }.deserialize(&mut de).and_then(|n| de.end().map(|()| n));
    match (r, shape.get()) {
        (_, Some(what)) => Err(FileError::Shape(what)),
        (Ok(n), None) => Ok(n),
        (Err(e), None) => Err(FileError::Json(e)),
    }
}

/// The whole file: a list of cases, or an object whose "cases" is one.
struct File<'a, 'b, T> {
    each: Each<'b, T>,
    shape: &'a Cell<Option<&'static str>>,
    case: PhantomData<T>,
}

impl<T> File<'_, '_, T> {
    fn wrong<E: de::Error>(&self, what: &'static str) -> Result<usize, E> {
        self.shape.set(Some(what));
        Err(E::custom(what))
    }
}

impl<'de, T: DeserializeOwned> DeserializeSeed<'de> for File<'_, '_, T> {
    type Value = usize;
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de, T: DeserializeOwned> Visitor<'de> for File<'_, '_, T> {
    type Value = usize;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list of cases or an object {\"cases\": [...]}")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<usize, A::Error> {
        each_case(seq, self.each)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<usize, A::Error> {
        let mut count = None;
        while let Some(key) = map.next_key::<String>()? {
            if key == "cases" && count.is_none() {
                count = Some(map.next_value_seed(CaseList {
                    each: &mut *self.each,
                    shape: self.shape,
                    case: PhantomData,
                })?);
            } else {
                map.next_value::<IgnoredAny>()?;
            }
        }
        match count {
            Some(n) => Ok(n),
            None => self.wrong("an object without \"cases\""),
        }
    }

    fn visit_unit<E: de::Error>(self) -> Result<usize, E> {
        self.wrong("null")
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<usize, E> {
        self.wrong("a boolean")
    }
    fn visit_i64<E: de::Error>(self, _: i64) -> Result<usize, E> {
        self.wrong("a number")
    }
    fn visit_u64<E: de::Error>(self, _: u64) -> Result<usize, E> {
        self.wrong("a number")
    }
    fn visit_f64<E: de::Error>(self, _: f64) -> Result<usize, E> {
        self.wrong("a number")
    }
    fn visit_str<E: de::Error>(self, _: &str) -> Result<usize, E> {
        self.wrong("a string")
    }
}

/// The value of "cases": it must be a list.
struct CaseList<'a, 'b, T> {
    each: Each<'b, T>,
    shape: &'a Cell<Option<&'static str>>,
    case: PhantomData<T>,
}

impl<'de, T: DeserializeOwned> DeserializeSeed<'de> for CaseList<'_, '_, T> {
    type Value = usize;
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de, T: DeserializeOwned> Visitor<'de> for CaseList<'_, '_, T> {
    type Value = usize;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list of cases")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<usize, A::Error> {
        each_case(seq, self.each)
    }

    fn visit_map<A: MapAccess<'de>>(self, _: A) -> Result<usize, A::Error> {
        self.shape.set(Some("\"cases\" that is not a list"));
        Err(de::Error::custom("\"cases\" that is not a list"))
    }

    fn visit_unit<E: de::Error>(self) -> Result<usize, E> {
        self.shape.set(Some("\"cases\" that is not a list"));
        Err(E::custom("\"cases\" that is not a list"))
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<usize, E> {
        self.visit_unit()
    }
    fn visit_i64<E: de::Error>(self, _: i64) -> Result<usize, E> {
        self.visit_unit()
    }
    fn visit_u64<E: de::Error>(self, _: u64) -> Result<usize, E> {
        self.visit_unit()
    }
    fn visit_f64<E: de::Error>(self, _: f64) -> Result<usize, E> {
        self.visit_unit()
    }
    fn visit_str<E: de::Error>(self, _: &str) -> Result<usize, E> {
        self.visit_unit()
    }
}

/// Each element of the list, one at a time.
fn each_case<'de, A: SeqAccess<'de>, T: DeserializeOwned>(mut seq: A, each: Each<'_, T>) -> Result<usize, A::Error> {
    let mut i = 0;
    while let Some(case) = seq.next_element::<T>()? {
        each(case, i);
        i += 1;
    }
    Ok(i)
}
