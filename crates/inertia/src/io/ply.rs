//! Stanford PLY (ASCII, binary little- and big-endian) through `ply-rs-bw`.
//!
//! The header is parsed by `ply-rs-bw`; the payload is then streamed one
//! element at a time with its per-element readers, keeping only vertex
//! positions and face index lists, so memory stays proportional to the
//! geometry actually present. Before reading, the header's counts are
//! checked against the bytes that follow it (binary: every element needs at
//! least its fixed-size part; an element without properties would be read
//! forever from no bytes, and is refused). Bytes after the last element are
//! ignored.
//!
//! The `vertex` element needs scalar `x`, `y`, `z` properties of any numeric
//! type; the `face` element a `vertex_indices` (or `vertex_index`) list of
//! any integer type. Polygons are fan-triangulated. Other elements are read
//! past and dropped.

use glam::DVec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{
    ElementDef, Encoding, Header, Property, PropertyAccess, PropertyAccessResult, PropertyType,
    ScalarType,
};

use super::{Body, Source};
use crate::InertiaError;

/// Loads the one body of a PLY file, named by the file stem.
pub(super) fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    let (vertices, triangles) = parse(bytes).map_err(|r| src.error(r))?;
    Ok(vec![src.body(
        src.stem().to_owned(),
        vertices,
        triangles,
    )?])
}

/// The properties of one element that a mesh needs; the rest are ignored.
#[derive(Default)]
struct Record {
    xyz: [Option<f64>; 3],
    indices: Option<Property>,
}

impl PropertyAccess for Record {
    fn new() -> Self {
        Self::default()
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        let axis = match name {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            "vertex_indices" | "vertex_index" => {
                self.indices = Some(property);
                return PropertyAccessResult::Set;
            }
            _ => return PropertyAccessResult::Ignored,
        };
        self.xyz[axis] = match property {
            Property::Char(v) => Some(f64::from(v)),
            Property::UChar(v) => Some(f64::from(v)),
            Property::Short(v) => Some(f64::from(v)),
            Property::UShort(v) => Some(f64::from(v)),
            Property::Int(v) => Some(f64::from(v)),
            Property::UInt(v) => Some(f64::from(v)),
            Property::Float(v) => Some(f64::from(v)),
            Property::Double(v) => Some(v),
            _ => None,
        };
        PropertyAccessResult::Set
    }
}

/// Reads positions and triangles from a whole PLY file.
fn parse(bytes: &[u8]) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), String> {
    if bytes.is_empty() {
        return Err("the file is empty".to_owned());
    }
    let parser = Parser::<Record>::new();
    let mut reader = Reader::new(bytes);
    // ply-rs-bw's messages go on with the offending line and the grammar's
    // expectations; the first line says what is wrong.
    let header = parser.read_header(&mut reader).map_err(|e| {
        let message = e.to_string();
        format!("header: {}", message.lines().next().unwrap_or_default())
    })?;
    let payload: &[u8] = reader.into_inner();
    let header_text = bytes.get(..bytes.len() - payload.len()).unwrap_or_default();
    check_header(&header, header_text, payload.len())?;
    let vertex_count = header.elements.get("vertex").map_or(0, |e| e.count);
    let mut stream = Stream {
        encoding: header.encoding,
        rest: payload,
        line: 0,
    };
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for (name, def) in &header.elements {
        for i in 0..def.count {
            let record = stream
                .next(&parser, def)
                .map_err(|e| format!("element '{name}' {i}: {e}"))?;
            match name.as_str() {
                "vertex" => {
                    let [Some(x), Some(y), Some(z)] = record.xyz else {
                        return Err(format!("vertex {i} lacks a scalar x, y or z"));
                    };
                    vertices.push(DVec3::new(x, y, z));
                }
                "face" => add_face(&record, i, vertex_count, &mut triangles)?,
                _ => {}
            }
        }
    }
    Ok((vertices, triangles))
}

/// Checks the header's structure and counts before any payload is read.
fn check_header(header: &Header, text: &[u8], payload_len: usize) -> Result<(), String> {
    let lines_starting = |word: &[u8]| {
        text.split(|&b| b == b'\n' || b == b'\r')
            .filter(|l| l.split(u8::is_ascii_whitespace).next() == Some(word))
            .count()
    };
    let properties: usize = header.elements.values().map(|e| e.properties.len()).sum();
    if lines_starting(b"element") != header.elements.len()
        || lines_starting(b"property") != properties
    {
        return Err("header repeats an element name or a property name".to_owned());
    }
    let vertex = header
        .elements
        .get("vertex")
        .ok_or("header has no 'vertex' element")?;
    for axis in ["x", "y", "z"] {
        match vertex.properties.get(axis).map(|p| &p.data_type) {
            Some(PropertyType::Scalar(_)) => {}
            _ => return Err(format!("'vertex' element has no scalar '{axis}' property")),
        }
    }
    let face = header
        .elements
        .get("face")
        .ok_or("header has no 'face' element (points alone enclose no volume)")?;
    let list = face
        .properties
        .get("vertex_indices")
        .or_else(|| face.properties.get("vertex_index"))
        .map(|p| &p.data_type);
    match list {
        Some(PropertyType::List(_, t)) if !matches!(t, ScalarType::Float | ScalarType::Double) => {}
        _ => {
            return Err(
                "'face' element has no integer list 'vertex_indices' or 'vertex_index'".to_owned(),
            );
        }
    }
    if header.encoding == Encoding::Ascii {
        return Ok(());
    }
    let mut needed: u128 = 0;
    for (name, def) in &header.elements {
        let size: usize = def
            .properties
            .values()
            .map(|p| match &p.data_type {
                PropertyType::Scalar(t) | PropertyType::List(t, _) => scalar_size(t),
            })
            .sum();
        if size == 0 && def.count > 0 {
            return Err(format!("element '{name}' has no properties"));
        }
        needed += def.count as u128 * size as u128;
    }
    if needed > payload_len as u128 {
        return Err(format!(
            "header declares elements needing at least {needed} bytes, \
             but only {payload_len} bytes follow it (the file may be truncated)"
        ));
    }
    Ok(())
}

/// Bytes of one binary scalar.
fn scalar_size(t: &ScalarType) -> usize {
    match t {
        ScalarType::Char | ScalarType::UChar => 1,
        ScalarType::Short | ScalarType::UShort => 2,
        ScalarType::Int | ScalarType::UInt | ScalarType::Float => 4,
        ScalarType::Double => 8,
    }
}

/// Fan-triangulates face `i` into `triangles`, checking its indices.
fn add_face(
    record: &Record,
    i: usize,
    vertex_count: usize,
    triangles: &mut Vec<[u32; 3]>,
) -> Result<(), String> {
    let list: Vec<i64> = match &record.indices {
        Some(Property::ListChar(l)) => l.iter().map(|&v| i64::from(v)).collect(),
        Some(Property::ListUChar(l)) => l.iter().map(|&v| i64::from(v)).collect(),
        Some(Property::ListShort(l)) => l.iter().map(|&v| i64::from(v)).collect(),
        Some(Property::ListUShort(l)) => l.iter().map(|&v| i64::from(v)).collect(),
        Some(Property::ListInt(l)) => l.iter().map(|&v| i64::from(v)).collect(),
        Some(Property::ListUInt(l)) => l.iter().map(|&v| i64::from(v)).collect(),
        _ => return Err(format!("face {i} has no integer vertex index list")),
    };
    if list.len() < 3 {
        return Err(format!(
            "face {i} has {} vertices, at least 3 are needed",
            list.len()
        ));
    }
    let index = |v: i64| {
        u32::try_from(v)
            .ok()
            .filter(|&u| (u as usize) < vertex_count)
            .ok_or_else(|| {
                format!("face {i} refers to vertex {v}, but the file has {vertex_count} vertices")
            })
    };
    let a = index(list[0])?;
    let mut b = index(list[1])?;
    for &v in &list[2..] {
        let c = index(v)?;
        triangles.push([a, b, c]);
        b = c;
    }
    Ok(())
}

/// The payload after the header, read one element at a time.
struct Stream<'a> {
    encoding: Encoding,
    rest: &'a [u8],
    /// Payload lines consumed so far (ASCII).
    line: usize,
}

impl<'a> Stream<'a> {
    /// Reads the next element of type `def`.
    fn next(&mut self, parser: &Parser<Record>, def: &ElementDef) -> Result<Record, String> {
        let result = match self.encoding {
            Encoding::BinaryLittleEndian => parser.read_little_endian_element(&mut self.rest, def),
            Encoding::BinaryBigEndian => parser.read_big_endian_element(&mut self.rest, def),
            Encoding::Ascii => {
                let line = self.next_line()?;
                let text = std::str::from_utf8(line)
                    .map_err(|_| format!("payload line {} is not text", self.line))?;
                parser.read_ascii_element(text, def)
            }
        };
        result.map_err(|e| {
            e.to_string()
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ")
        })
    }

    /// The next non-blank payload line, without its line break.
    fn next_line(&mut self) -> Result<&'a [u8], String> {
        loop {
            if self.rest.is_empty() {
                return Err("unexpected end of file (the file may be truncated)".to_owned());
            }
            let end = self
                .rest
                .iter()
                .position(|&b| b == b'\n')
                .unwrap_or(self.rest.len());
            let (line, rest) = self.rest.split_at(end);
            self.rest = rest.get(1..).unwrap_or_default();
            self.line += 1;
            let line = line.strip_suffix(b"\r").unwrap_or(line);
            if !line.iter().all(u8::is_ascii_whitespace) {
                return Ok(line);
            }
        }
    }
}
