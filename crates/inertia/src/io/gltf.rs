//! glTF 2.0, as `.gltf` JSON or `.glb` binary, through the `gltf` crate's
//! document model.
//!
//! One body per mesh *instance*: every node with a mesh in the default scene
//! (or, without a default scene, under every root node), its positions
//! carried through the node's global transform (the product of the local
//! matrix or translation·rotation·scale of it and its ancestors, in `f64`).
//! A transform with negative determinant mirrors the mesh, so its triangles
//! are re-wound to stay outward-facing, as the specification prescribes.
//! Bodies are named by the node's name, else the mesh's, else `mesh{i}`.
//!
//! Primitives of mode `TRIANGLES`, `TRIANGLE_STRIP` and `TRIANGLE_FAN` are
//! read (strips and fans skip their degenerate stitching triangles); points
//! and lines carry no volume and are skipped, and a mesh with nothing else
//! makes no body. `POSITION` must be `f32` `VEC3`; indices `u8`, `u16` or
//! `u32`, or absent. Each mesh is read once however often it is instanced;
//! the output holds one transformed copy per instance.
//!
//! The node hierarchy must be a tree: a node reached twice (a cycle, or two
//! parents) is an error rather than endless or exponential work.

use std::borrow::Cow;

use ::gltf::mesh::Mode;
use ::gltf::scene::Transform;
use ::gltf::{Document, Node, Semantic};
use glam::{DMat4, DQuat, DVec3};

use super::{Body, Source, vertex_index};
use crate::InertiaError;

mod accessor;
mod buffers;

/// One mesh's geometry in its own coordinates.
type Geometry = (Vec<DVec3>, Vec<[u32; 3]>);

/// Loads one body per mesh instance.
pub(super) fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    let container = buffers::split(bytes).map_err(|r| src.error(r))?;
    let doc = document(container.json).map_err(|r| src.error(r))?;
    let data = buffers::load(&doc, container.bin, src)?;
    let mut geometry: Vec<Option<Option<Geometry>>> = vec![None; doc.meshes().len()];
    let mut bodies = Vec::new();
    for (node, transform) in instances(&doc).map_err(|r| src.error(r))? {
        let Some(mesh) = node.mesh() else { continue };
        let Some(slot) = geometry.get_mut(mesh.index()) else {
            continue;
        };
        if slot.is_none() {
            *slot = Some(read_mesh(&mesh, &data).map_err(|r| src.error(r))?);
        }
        let Some(Some((vertices, triangles))) = slot.as_ref() else {
            continue;
        };
        let vertices = vertices
            .iter()
            .map(|&v| transform.transform_point3(v))
            .collect();
        let triangles = if transform.determinant() < 0.0 {
            triangles.iter().map(|&[a, b, c]| [a, c, b]).collect()
        } else {
            triangles.clone()
        };
        let name = node
            .name()
            .or(mesh.name())
            .map_or_else(|| format!("mesh{}", mesh.index()), str::to_owned);
        bodies.push(src.body(name, vertices, triangles)?);
    }
    if bodies.is_empty() {
        return Err(src.error("the scene has no triangle mesh"));
    }
    Ok(bodies)
}

/// Parses and validates the JSON document.
fn document(json: &[u8]) -> Result<Document, String> {
    if json.is_empty() {
        return Err("the file is empty".to_owned());
    }
    let root: ::gltf::json::Root =
        ::gltf::json::deserialize::from_slice(json).map_err(|e| format!("JSON: {e}"))?;
    // gltf-json's validation indexes `accessors[POSITION]` unchecked, and
    // panics on an out-of-range index: check it first.
    let positions = ::gltf::json::validation::Checked::Valid(Semantic::Positions);
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            if let Some(index) = primitive.attributes.get(&positions)
                && index.value() >= root.accessors.len()
            {
                return Err(format!(
                    "mesh {m} primitive {p}: POSITION accessor {} does not exist ({} accessors)",
                    index.value(),
                    root.accessors.len()
                ));
            }
        }
    }
    Document::from_json(root).map_err(|e| format!("invalid glTF document: {e}"))
}

/// Every node of the scene with its global transform, parents first.
fn instances(doc: &Document) -> Result<Vec<(Node<'_>, DMat4)>, String> {
    let roots: Vec<Node<'_>> = match doc.default_scene() {
        Some(scene) => scene.nodes().collect(),
        None => {
            let mut has_parent = vec![false; doc.nodes().len()];
            for child in doc.nodes().flat_map(|n| n.children()) {
                if let Some(flag) = has_parent.get_mut(child.index()) {
                    *flag = true;
                }
            }
            doc.nodes()
                .filter(|n| !has_parent.get(n.index()).copied().unwrap_or(false))
                .collect()
        }
    };
    let mut visited = vec![false; doc.nodes().len()];
    let mut stack: Vec<(Node<'_>, DMat4)> = roots
        .into_iter()
        .rev()
        .map(|n| (n, DMat4::IDENTITY))
        .collect();
    let mut out = Vec::new();
    while let Some((node, parent)) = stack.pop() {
        let i = node.index();
        match visited.get_mut(i) {
            Some(seen) if !*seen => *seen = true,
            _ => {
                return Err(format!(
                    "node {i} is reached twice: the node hierarchy is not a tree"
                ));
            }
        }
        let global = parent * local_transform(&node)?;
        let children: Vec<Node<'_>> = node.children().collect();
        stack.extend(children.into_iter().rev().map(|child| (child, global)));
        out.push((node, global));
    }
    Ok(out)
}

/// A node's local transform in `f64`.
fn local_transform(node: &Node<'_>) -> Result<DMat4, String> {
    let wide = |v: [f32; 3]| DVec3::from_array(v.map(f64::from));
    match node.transform() {
        Transform::Matrix { matrix } => Ok(DMat4::from_cols_array_2d(
            &matrix.map(|column| column.map(f64::from)),
        )),
        Transform::Decomposed {
            translation,
            rotation,
            scale,
        } => {
            let q = DQuat::from_array(rotation.map(f64::from));
            let length = q.length();
            if !(length.is_finite() && length > 0.0) {
                return Err(format!(
                    "node {} has a zero or non-finite rotation quaternion",
                    node.index()
                ));
            }
            Ok(DMat4::from_scale_rotation_translation(
                wide(scale),
                q * length.recip(),
                wide(translation),
            ))
        }
    }
}

/// Reads a mesh's triangle primitives into one vertex and triangle list,
/// or `None` if it has no triangle primitive.
fn read_mesh(
    mesh: &::gltf::Mesh<'_>,
    buffers: &[Cow<'_, [u8]>],
) -> Result<Option<Geometry>, String> {
    let mut vertices: Vec<DVec3> = Vec::new();
    let mut triangles = Vec::new();
    let mut any = false;
    for primitive in mesh.primitives() {
        let mode = primitive.mode();
        if !matches!(
            mode,
            Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
        ) {
            continue;
        }
        any = true;
        let at = format!("mesh {} primitive {}", mesh.index(), primitive.index());
        let positions = primitive
            .get(&Semantic::Positions)
            .ok_or_else(|| format!("{at} has no POSITION"))?;
        let positions =
            accessor::positions(&positions, buffers).map_err(|r| format!("{at}: {r}"))?;
        let count = positions.len();
        let indices = match primitive.indices() {
            Some(a) => accessor::indices(&a, buffers).map_err(|r| format!("{at}: {r}"))?,
            None => (0..vertex_index(count)?).collect(),
        };
        if let Some((k, v)) = indices
            .iter()
            .enumerate()
            .find(|&(_, &v)| v as usize >= count)
        {
            return Err(format!(
                "{at}: index {k} is {v}, but the primitive has {count} vertices"
            ));
        }
        let base = vertex_index(vertices.len())?;
        vertex_index(vertices.len() + count)?;
        let corners = |t: [u32; 3]| t.map(|i| base + i);
        match mode {
            Mode::Triangles => {
                let (list, rest) = indices.as_chunks::<3>();
                if !rest.is_empty() {
                    return Err(format!(
                        "{at}: {} triangle indices are not a multiple of 3",
                        indices.len()
                    ));
                }
                triangles.extend(list.iter().map(|&t| corners(t)));
            }
            Mode::TriangleStrip => triangles.extend(
                indices
                    .windows(3)
                    .enumerate()
                    .map(|(i, w)| {
                        if i % 2 == 0 {
                            [w[0], w[1], w[2]]
                        } else {
                            [w[1], w[0], w[2]]
                        }
                    })
                    .filter(|&t| !degenerate(t))
                    .map(corners),
            ),
            _ => {
                if let Some((&first, rest)) = indices.split_first() {
                    triangles.extend(
                        rest.windows(2)
                            .map(|w| [first, w[0], w[1]])
                            .filter(|&t| !degenerate(t))
                            .map(corners),
                    );
                }
            }
        }
        vertices.extend(positions);
    }
    Ok(any.then_some((vertices, triangles)))
}

/// Whether a triangle repeats a vertex index.
fn degenerate([a, b, c]: [u32; 3]) -> bool {
    a == b || b == c || a == c
}
