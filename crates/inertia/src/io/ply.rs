//! Stanford PLY (ASCII, binary little- and big-endian): the header through
//! `ply-rs-bw`, the payload read here.
//!
//! The header is parsed by `ply-rs-bw` and checked against the bytes that
//! follow it (binary: every element needs at least its fixed-size part; an
//! element without properties would be read forever from no bytes, and is
//! refused). The payload is then read element by element straight into the
//! vertex and triangle lists, keeping only vertex positions and face index
//! lists. (`ply-rs-bw`'s own element readers were used before: they match
//! every ASCII line against a PEG grammar, look each property up by name and
//! build a `Vec` per face list, ≈ 40 % of a whole `kreisel inertia` run on an
//! ASCII PLY; reading the layout the header declares directly does the same
//! checks in a fraction of that.) Bytes after the last element are ignored.
//!
//! The `vertex` element needs scalar `x`, `y`, `z` properties of any numeric
//! type; the `face` element a `vertex_indices` (or `vertex_index`) list of
//! any integer type. Polygons are fan-triangulated. Other elements and
//! properties are read past (and checked to be numbers of their type).
//!
//! ASCII: one element per non-blank line, values separated by blanks, each
//! parsed as its declared type (`float` as `f32`, then widened exactly); a
//! line with fewer or more values than its element declares is an error.
//! A large file of just a `vertex` and then a `face` element has its faces
//! read on a second thread while its vertices are read (with the same
//! results and errors as one thread).

use glam::DVec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{DefaultElement, ElementDef, Encoding, Header, PropertyType, ScalarType};

use super::text_scan::{next_line, next_plain_digits, next_word, parse_float, parse_integer};
use super::{Body, Source};
use crate::InertiaError;

/// Loads the one body of a PLY file, named by the file stem.
pub(super) fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    let (vertices, triangles) = parse(bytes).map_err(|r| src.error(r))?;
    Ok(vec![src.indexed_body(
        src.stem().to_owned(),
        vertices,
        triangles,
    )?])
}

/// What a property of an element is used for.
#[derive(Clone, Copy, PartialEq)]
enum Role {
    /// A vertex coordinate: 0, 1, 2 for x, y, z.
    Axis(usize),
    /// The face's vertex index list.
    Indices,
    /// Read past.
    Skip,
}

/// One property as the payload stores it.
#[derive(Clone)]
struct Field {
    role: Role,
    /// `Some(count type)` for a list.
    count: Option<ScalarType>,
    value: ScalarType,
}

/// The properties of an element in order, with their roles.
fn fields(element: &str, def: &ElementDef) -> Vec<Field> {
    def.properties
        .iter()
        .map(|(name, p)| {
            let role = match (element, name.as_str()) {
                ("vertex", "x") => Role::Axis(0),
                ("vertex", "y") => Role::Axis(1),
                ("vertex", "z") => Role::Axis(2),
                ("face", "vertex_indices" | "vertex_index") => Role::Indices,
                _ => Role::Skip,
            };
            let (count, value) = match &p.data_type {
                PropertyType::Scalar(t) => (None, t.clone()),
                PropertyType::List(c, t) => (Some(c.clone()), t.clone()),
            };
            Field { role, count, value }
        })
        .collect()
}

/// Reads positions and triangles from a whole PLY file.
fn parse(bytes: &[u8]) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), String> {
    if bytes.is_empty() {
        return Err("the file is empty".to_owned());
    }
    let parser = Parser::<DefaultElement>::new();
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
    let mut values = Values {
        encoding: header.encoding,
        rest: payload,
        line: 0,
        words: &[],
    };
    let mut mesh = Mesh {
        // The header's counts were checked against the payload's length
        // only for binary files; text allocations grow with what is read.
        vertices: Vec::with_capacity(if values.encoding == Encoding::Ascii {
            0
        } else {
            vertex_count
        }),
        triangles: Vec::new(),
        vertex_count,
    };
    let elements: Vec<(&String, &ElementDef)> = header.elements.iter().collect();
    let mut done = 0;
    if let [(vertex_name, vertex_def), (face_name, face_def)] = elements[..]
        && values.encoding == Encoding::Ascii
        && payload.len() >= PARALLEL_BYTES
        && vertex_name == "vertex"
        && face_name == "face"
    {
        let faces = std::thread::scope(|scope| {
            // No thread (the system refused one): the faces are read after.
            let faces = std::thread::Builder::new()
                .spawn_scoped(scope, || faces_ahead(payload, vertex_count, face_def))
                .ok();
            read_elements(vertex_name, vertex_def, &mut values, &mut mesh)?;
            Ok::<_, String>(faces.and_then(|f| f.join().ok()).flatten())
        })?;
        let vertices_end = payload.len() - values.rest.len();
        if let Some(faces) = faces
            && values.line == vertex_count
            && faces.start == vertices_end
        {
            mesh.triangles = faces.result?;
            return Ok((mesh.vertices, mesh.triangles));
        }
        // A blank line among the vertices: the faces from where they end.
        done = 1;
    }
    for &(name, def) in &elements[done..] {
        read_elements(name, def, &mut values, &mut mesh)?;
    }
    Ok((mesh.vertices, mesh.triangles))
}

/// Payload bytes from which an ASCII file's faces are read on a second
/// thread while the vertices are read (smaller files: one thread). This
/// saves wall time, not CPU time: the second thread first scans the vertex
/// lines for where they end (figures in BENCHMARKS.md, "End to end").
const PARALLEL_BYTES: usize = 1 << 20;

/// The faces of an ASCII file, read ahead on the assumption that the
/// `vertex` lines (the first `vertex_count` lines of the payload) are all
/// non-blank. The caller checks that assumption when the vertices are read
/// (then this is what reading on from there gives, error and line numbers
/// included) and reads the faces itself otherwise.
fn faces_ahead(payload: &[u8], vertex_count: usize, def: &ElementDef) -> Option<FacesAhead> {
    let mut rest = payload;
    for _ in 0..vertex_count {
        next_line(&mut rest)?;
    }
    let start = payload.len() - rest.len();
    let mut values = Values {
        encoding: Encoding::Ascii,
        rest,
        line: vertex_count,
        words: &[],
    };
    let mut mesh = Mesh {
        vertices: Vec::new(),
        triangles: Vec::new(),
        vertex_count,
    };
    let result = read_elements("face", def, &mut values, &mut mesh).map(|()| mesh.triangles);
    Some(FacesAhead { start, result })
}

/// See [`faces_ahead`].
struct FacesAhead {
    /// The payload offset the faces were read from.
    start: usize,
    /// The triangles, or the error reading them.
    result: Result<Vec<[u32; 3]>, String>,
}

/// Reads every element of one type.
fn read_elements(
    name: &str,
    def: &ElementDef,
    values: &mut Values<'_>,
    mesh: &mut Mesh,
) -> Result<(), String> {
    let fields = fields(name, def);
    for i in 0..def.count {
        values
            .start_element()
            .and_then(|()| mesh.read_element(name, i, &fields, values))
            .and_then(|()| values.end_element())
            .map_err(|e| format!("element '{name}' {i}: {e}"))?;
    }
    Ok(())
}

/// The mesh being read.
struct Mesh {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    /// The header's vertex count, which face indices must stay below.
    vertex_count: usize,
}

impl Mesh {
    /// Reads element `i` of type `name` with these fields.
    fn read_element(
        &mut self,
        name: &str,
        i: usize,
        fields: &[Field],
        values: &mut Values<'_>,
    ) -> Result<(), String> {
        let mut xyz = [0.0; 3];
        for field in fields {
            let Some(count_type) = &field.count else {
                let v = values.scalar(&field.value)?;
                if let Role::Axis(axis) = field.role {
                    xyz[axis] = v;
                }
                continue;
            };
            let count = values.count(count_type)?;
            if field.role != Role::Indices {
                for _ in 0..count {
                    values.scalar(&field.value)?;
                }
                continue;
            }
            if count < 3 {
                return Err(format!(
                    "face {i} has {count} vertices, at least 3 are needed"
                ));
            }
            // Fan triangulation as the indices arrive.
            let mut index = || -> Result<u32, String> {
                let v = values.integer(&field.value)?;
                u32::try_from(v)
                    .ok()
                    .filter(|&u| (u as usize) < self.vertex_count)
                    .ok_or_else(|| {
                        format!(
                            "face {i} refers to vertex {v}, but the file has {} vertices",
                            self.vertex_count
                        )
                    })
            };
            let a = index()?;
            let mut b = index()?;
            for _ in 2..count {
                let c = index()?;
                self.triangles.push([a, b, c]);
                b = c;
            }
        }
        if name == "vertex" {
            self.vertices.push(DVec3::from_array(xyz));
        }
        Ok(())
    }
}

/// The payload's values, read in the header's order.
struct Values<'a> {
    encoding: Encoding,
    rest: &'a [u8],
    /// Payload lines consumed so far (ASCII).
    line: usize,
    /// The rest of the current line (ASCII), its values separated by ASCII
    /// blanks (as `str::split_ascii_whitespace` separates them).
    words: &'a [u8],
}

impl<'a> Values<'a> {
    /// Moves to the next element's line (ASCII; nothing for binary).
    fn start_element(&mut self) -> Result<(), String> {
        if self.encoding != Encoding::Ascii {
            return Ok(());
        }
        let line = self.next_line()?;
        if !line.is_ascii() && core::str::from_utf8(line).is_err() {
            return Err(format!("payload line {} is not text", self.line));
        }
        self.words = line;
        Ok(())
    }

    /// Checks that an element's line has no values left over (ASCII).
    fn end_element(&mut self) -> Result<(), String> {
        match next_word(&mut self.words, |b| b.is_ascii_whitespace()) {
            Some(extra) => Err(format!(
                "payload line {} has more values than the element declares ('{}')",
                self.line,
                String::from_utf8_lossy(extra)
            )),
            None => Ok(()),
        }
    }

    /// The next non-blank payload line, without its line break.
    fn next_line(&mut self) -> Result<&'a [u8], String> {
        loop {
            let Some(line) = next_line(&mut self.rest) else {
                return Err("unexpected end of file (the file may be truncated)".to_owned());
            };
            self.line += 1;
            if !line.iter().all(u8::is_ascii_whitespace) {
                return Ok(line);
            }
        }
    }

    /// The next ASCII value.
    fn word(&mut self, t: &ScalarType) -> Result<&'a [u8], String> {
        next_word(&mut self.words, |b| b.is_ascii_whitespace()).ok_or_else(|| {
            format!(
                "payload line {} ends before a value of type {}",
                self.line,
                type_name(t)
            )
        })
    }

    /// The next `N` binary bytes in file order, or the end-of-file error.
    fn bytes<const N: usize>(&mut self) -> Result<[u8; N], String> {
        let Some((head, rest)) = self.rest.split_first_chunk::<N>() else {
            return Err("unexpected end of file (the file may be truncated)".to_owned());
        };
        self.rest = rest;
        let mut b = *head;
        if self.encoding == Encoding::BinaryBigEndian {
            b.reverse();
        }
        // Little-endian from here on.
        Ok(b)
    }

    /// The next value of an integer type, widened.
    fn integer(&mut self, t: &ScalarType) -> Result<i64, String> {
        if self.encoding == Encoding::Ascii {
            if let Some((v, word)) = next_plain_digits(&mut self.words, |b| b.is_ascii_whitespace())
            {
                // What `parse_integer` gives for plain digits.
                let fits = match t {
                    ScalarType::Char => i8::try_from(v).is_ok(),
                    ScalarType::UChar => u8::try_from(v).is_ok(),
                    ScalarType::Short => i16::try_from(v).is_ok(),
                    ScalarType::UShort => u16::try_from(v).is_ok(),
                    ScalarType::Int => i32::try_from(v).is_ok(),
                    ScalarType::UInt => u32::try_from(v).is_ok(),
                    ScalarType::Float | ScalarType::Double => false,
                };
                return if fits { Ok(v) } else { Err(bad_value(word, t)) };
            }
            let word = self.word(t)?;
            let value = match t {
                ScalarType::Char => parse_integer::<i8>(word).map(i64::from),
                ScalarType::UChar => parse_integer::<u8>(word).map(i64::from),
                ScalarType::Short => parse_integer::<i16>(word).map(i64::from),
                ScalarType::UShort => parse_integer::<u16>(word).map(i64::from),
                ScalarType::Int => parse_integer::<i32>(word).map(i64::from),
                ScalarType::UInt => parse_integer::<u32>(word).map(i64::from),
                ScalarType::Float | ScalarType::Double => None,
            };
            return value.ok_or_else(|| bad_value(word, t));
        }
        Ok(match t {
            ScalarType::Char => i64::from(i8::from_le_bytes(self.bytes()?)),
            ScalarType::UChar => i64::from(u8::from_le_bytes(self.bytes()?)),
            ScalarType::Short => i64::from(i16::from_le_bytes(self.bytes()?)),
            ScalarType::UShort => i64::from(u16::from_le_bytes(self.bytes()?)),
            ScalarType::Int => i64::from(i32::from_le_bytes(self.bytes()?)),
            ScalarType::UInt => i64::from(u32::from_le_bytes(self.bytes()?)),
            ScalarType::Float | ScalarType::Double => {
                return Err(format!("{} is not an integer type", type_name(t)));
            }
        })
    }

    /// The next value of any scalar type, as `f64` (exact for every type).
    fn scalar(&mut self, t: &ScalarType) -> Result<f64, String> {
        match t {
            ScalarType::Float | ScalarType::Double if self.encoding == Encoding::Ascii => {
                let word = self.word(t)?;
                let value = match t {
                    ScalarType::Float => parse_float::<f32>(word).map(f64::from),
                    _ => parse_float::<f64>(word),
                };
                value.ok_or_else(|| bad_value(word, t))
            }
            ScalarType::Float => Ok(f64::from(f32::from_le_bytes(self.bytes()?))),
            ScalarType::Double => Ok(f64::from_le_bytes(self.bytes()?)),
            // Integers of at most 32 bits convert to f64 exactly.
            _ => self.integer(t).map(|v| v as f64),
        }
    }

    /// A list's length.
    fn count(&mut self, t: &ScalarType) -> Result<usize, String> {
        let n = self.integer(t)?;
        usize::try_from(n).map_err(|_| format!("negative list length {n}"))
    }
}

/// The error for a word that is not a value of type `t`.
fn bad_value(word: &[u8], t: &ScalarType) -> String {
    format!(
        "'{}' is not a {} value",
        String::from_utf8_lossy(word),
        type_name(t)
    )
}

/// The PLY name of a scalar type.
fn type_name(t: &ScalarType) -> &'static str {
    match t {
        ScalarType::Char => "char",
        ScalarType::UChar => "uchar",
        ScalarType::Short => "short",
        ScalarType::UShort => "ushort",
        ScalarType::Int => "int",
        ScalarType::UInt => "uint",
        ScalarType::Float => "float",
        ScalarType::Double => "double",
    }
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

#[cfg(test)]
mod tests {
    use ply_rs_bw::ply::Property;

    use super::*;

    /// A PLY with properties before, between and after the used ones, `int`
    /// and `double` coordinates, and a `ushort`-counted `uint` index list.
    const ODD: &str = "ply\nformat ascii 1.0\nelement vertex 4\nproperty uchar red\n\
        property float x\nproperty int y\nproperty double z\nproperty list uchar short extra\n\
        element face 2\nproperty float quality\nproperty list ushort uint vertex_indices\n\
        element edge 1\nproperty int a\nend_header\n\
        1 0.1 0 0 2 5 -6\n2 1 0 0.30000000000000004 0\n3 0 1 0 1 -1\n4 0 0 1 0\n\
        0.5 3 0 2 1\n1.5 4 0 1 3 2\n7\n";

    /// The same file read by `ply-rs-bw`'s own element reader.
    fn reference(bytes: &[u8]) -> (Vec<DVec3>, Vec<Vec<i64>>) {
        let ply = Parser::<DefaultElement>::new()
            .read_ply(&mut &bytes[..])
            .unwrap();
        let number = |p: &Property| match *p {
            Property::UChar(v) => f64::from(v),
            Property::Int(v) => f64::from(v),
            Property::Float(v) => f64::from(v),
            Property::Double(v) => v,
            _ => panic!("{p:?}"),
        };
        let vertices = ply.payload["vertex"]
            .iter()
            .map(|e| DVec3::new(number(&e["x"]), number(&e["y"]), number(&e["z"])))
            .collect();
        let faces = ply.payload["face"]
            .iter()
            .map(|e| match &e["vertex_indices"] {
                Property::ListUInt(l) => l.iter().map(|&v| i64::from(v)).collect(),
                Property::ListInt(l) => l.iter().map(|&v| i64::from(v)).collect(),
                p => panic!("{p:?}"),
            })
            .collect();
        (vertices, faces)
    }

    fn fan(faces: &[Vec<i64>]) -> Vec<[u32; 3]> {
        faces
            .iter()
            .flat_map(|f| (2..f.len()).map(move |k| [f[0], f[k - 1], f[k]].map(|v| v as u32)))
            .collect()
    }

    #[test]
    fn reads_what_ply_rs_bw_reads_in_every_encoding() {
        let header_end = ODD.find("end_header\n").unwrap() + "end_header\n".len();
        let (vertices, faces) = parse(ODD.as_bytes()).unwrap();
        let (ref_vertices, ref_faces) = reference(ODD.as_bytes());
        assert_eq!(vertices, ref_vertices);
        // `float` is read as f32: 0.1 is not 0.1_f64.
        assert_eq!(vertices[0].x, f64::from(0.1_f32));
        assert_eq!(faces, fan(&ref_faces));
        // The same data in binary, both byte orders, written from the text.
        for (format, big) in [("binary_little_endian", false), ("binary_big_endian", true)] {
            let mut bytes = ODD[..header_end].replace("ascii", format).into_bytes();
            let types: [&[&str]; 3] = [
                &["u1", "f4", "i4", "f8", "l1", "i2"],
                &["f4", "l2", "u4"],
                &["i4"],
            ];
            let body = &ODD[header_end..];
            let mut lines = body.lines();
            for (element, count) in [(0, 4), (1, 2), (2, 1)] {
                for _ in 0..count {
                    let mut words = lines.next().unwrap().split(' ');
                    let mut put = |t: &str, w: &str| {
                        let mut b = match t {
                            "u1" | "l1" => vec![w.parse::<u8>().unwrap()],
                            "l2" => w.parse::<u16>().unwrap().to_le_bytes().to_vec(),
                            "i2" => w.parse::<i16>().unwrap().to_le_bytes().to_vec(),
                            "i4" => w.parse::<i32>().unwrap().to_le_bytes().to_vec(),
                            "u4" => w.parse::<u32>().unwrap().to_le_bytes().to_vec(),
                            "f4" => w.parse::<f32>().unwrap().to_le_bytes().to_vec(),
                            "f8" => w.parse::<f64>().unwrap().to_le_bytes().to_vec(),
                            _ => unreachable!(),
                        };
                        if big {
                            b.reverse();
                        }
                        bytes.extend(b);
                    };
                    let mut pending = types[element].iter();
                    while let Some(&t) = pending.next() {
                        let w = words.next().unwrap();
                        put(t, w);
                        if t.starts_with('l') {
                            let item = pending.next().unwrap();
                            for _ in 0..w.parse::<usize>().unwrap() {
                                put(item, words.next().unwrap());
                            }
                        }
                    }
                }
            }
            let (v, f) = parse(&bytes).unwrap();
            let (rv, rf) = reference(&bytes);
            assert_eq!((v, f), (rv, fan(&rf)), "{format}");
        }
    }

    /// An ASCII PLY of `n` vertices and `n − 2` fan triangles, over
    /// [`PARALLEL_BYTES`] of payload for n = 40 000; `extra_element` adds an
    /// empty third element, which makes the parse take one thread.
    fn big_ascii(n: usize, extra_element: bool) -> String {
        let extra = if extra_element {
            "element edge 0\nproperty int a\n"
        } else {
            ""
        };
        let mut text = format!(
            "ply\nformat ascii 1.0\nelement vertex {n}\nproperty double x\nproperty double y\n\
             property double z\nelement face {}\nproperty list uchar int vertex_indices\n\
             {extra}end_header\n",
            n - 2
        );
        for i in 0..n {
            let t = i as f64 * 0.001;
            text += &format!("{} {} {}\n", t.cos(), t.sin(), t * 0.1);
        }
        for i in 1..n - 1 {
            text += &format!("3 0 {i} {}\n", i + 1);
        }
        text
    }

    #[test]
    fn faces_read_ahead_on_a_second_thread_equal_one_thread() {
        let n = 40_000;
        let (one, two) = (big_ascii(n, true), big_ascii(n, false));
        assert!(two.len() - two.find("end_header").unwrap() > PARALLEL_BYTES);
        let face = |k: usize| format!("\n3 0 {k} {}\n", k + 1);
        let vertex_line = |text: &str, k: usize| {
            let start = text.find("end_header\n").unwrap() + 11;
            text[start..]
                .split_inclusive('\n')
                .nth(k)
                .unwrap()
                .to_owned()
        };
        // Each edit is made to both texts: the results (and errors, with
        // their element and line numbers) must agree.
        let edits: Vec<(String, String)> = vec![
            (String::new(), String::new()),
            (face(30_000), "\n3 0 30000 x\n".to_owned()),
            (face(30_000), "\n3 0 30000 40000\n".to_owned()),
            (face(30_000), "\n\n  \n3 0 30000 30001 7\n".to_owned()),
            (face(39_997), "\n3 0 39997\n".to_owned()),
            (vertex_line(&two, 123), "1 2 three\n".to_owned()),
            (vertex_line(&two, 123), "\n1 2 3\n".to_owned()),
        ];
        for (from, to) in edits {
            let (a, b) = if from.is_empty() {
                (one.clone(), two.clone())
            } else {
                (one.replacen(&from, &to, 1), two.replacen(&from, &to, 1))
            };
            assert_ne!(from.is_empty(), a != one, "{to:?} applied");
            let (sequential, parallel) = (parse(a.as_bytes()), parse(b.as_bytes()));
            assert_eq!(sequential, parallel, "{to:?}");
            if from.is_empty() || to.starts_with("\n1 2 3") {
                assert_eq!(parallel.unwrap().1.len(), n - 2);
            } else {
                assert!(parallel.is_err(), "{to:?}");
            }
        }
    }

    #[test]
    fn malformed_payloads_are_errors() {
        let cases = [
            ("1 0.1 0 0 2 5 -6\n", "1 0.1 0 0 2 5 -6 9\n", "more values"),
            (
                "1 0.1 0 0 2 5 -6\n",
                "1 0.1 0 0 2 5\n",
                "ends before a value of type short",
            ),
            (
                "1 0.1 0 0 2 5 -6\n",
                "1 0.1 0.5 0 2 5 -6\n",
                "'0.5' is not a int value",
            ),
            (
                "0.5 3 0 2 1\n",
                "0.5 3 0 2 4\n",
                "face 0 refers to vertex 4",
            ),
            ("0.5 3 0 2 1\n", "0.5 2 0 2\n", "face 0 has 2 vertices"),
            (
                "0.5 3 0 2 1\n",
                "0.5 4000000000 0 2 1\n",
                "not a ushort value",
            ),
            (
                "0.5 3 0 2 1\n",
                "0.5 65535 0 2 1\n",
                "ends before a value of type uint",
            ),
            ("7\n", "", "unexpected end of file"),
        ];
        for (from, to, expected) in cases {
            let text = ODD.replacen(from, to, 1);
            let err = parse(text.as_bytes()).unwrap_err();
            assert!(err.contains(expected), "{to:?}: {err}");
        }
    }
}
