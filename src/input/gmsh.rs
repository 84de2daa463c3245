//! Gmsh's mesh format 4.1, ASCII and binary: the nodes, the elements and the physical groups
//! that name them, as Gmsh writes them (`gmsh -2 -format msh41 part.geo`, or the gmsh Python
//! package's `gmsh.write("part.msh")`). Reference: the Gmsh manual, §"MSH file format".
//!
//! Only what a 2D body needs is kept: every node's x and y, the elements of dimension 1 and 2
//! with their entity, and each entity's physical tags with their names. Sections this reader
//! does not use (`$NodeData`, `$Periodic`, …) are skipped. Binary files must be
//! little-endian with 8-byte `size_t`, as Gmsh writes them on every common machine.

use std::collections::HashMap;
use std::path::Path;

/// Errors reading a `.msh` file.
#[derive(Debug, thiserror::Error)]
pub enum GmshError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// Why.
        source: std::io::Error,
    },
    /// Not format 4.1.
    #[error("format {version}: wearfem reads Gmsh's format 4.1 (in Gmsh: Mesh.MshFileVersion = 4.1, or gmsh.option.setNumber(\"Mesh.MshFileVersion\", 4.1))")]
    Version {
        /// The version the file declares.
        version: String,
    },
    /// The file ends early or a value cannot be read.
    #[error("section ${section}: {what}")]
    Malformed {
        /// The section being read.
        section: String,
        /// What went wrong.
        what: String,
    },
    /// An element type this reader does not know the node count of.
    #[error("element {tag} has Gmsh type {kind}, which wearfem does not read (it reads points, lines of order 1 and 2, quadrangles of 4, 8 and 9 nodes, and triangles, which it then refuses)")]
    UnknownType {
        /// The element's tag.
        tag: usize,
        /// Its Gmsh type number.
        kind: i32,
    },
}

/// One element of the file.
#[derive(Clone, Debug)]
pub struct GmshElement {
    /// The element's tag in the file.
    pub tag: usize,
    /// Gmsh element type (1: 2-node line, 8: 3-node line, 3: 4-node quadrangle, 16: 8-node,
    /// 10: 9-node quadrangle, 2: triangle, 9: 6-node triangle, 15: point).
    pub kind: i32,
    /// Dimension of its entity (0 point, 1 curve, 2 surface).
    pub dim: i32,
    /// Tag of its entity.
    pub entity: i32,
    /// Node tags, in Gmsh's order (corners first).
    pub nodes: Vec<usize>,
}

/// The contents of a `.msh` file that a 2D body needs.
#[derive(Clone, Debug, Default)]
pub struct GmshMesh {
    /// Node tag → [x, y] (mm: the file's units are taken as mm; y is wearfem's z).
    pub nodes: HashMap<usize, [f64; 2]>,
    /// Elements of dimension 1 and 2.
    pub elements: Vec<GmshElement>,
    /// (dim, entity tag) → the entity's physical tags.
    pub entity_groups: HashMap<(i32, i32), Vec<i32>>,
    /// (dim, physical tag) → the group's name.
    pub group_names: HashMap<(i32, i32), String>,
}

impl GmshMesh {
    /// The physical groups of dimension `dim` by name: name → physical tag.
    pub fn groups(&self, dim: i32) -> HashMap<&str, i32> {
        self.group_names
            .iter()
            .filter(|((d, _), _)| *d == dim)
            .map(|((_, tag), name)| (name.as_str(), *tag))
            .collect()
    }

    /// The names of the physical groups the element belongs to (through its entity).
    pub fn element_groups<'a>(&'a self, element: &GmshElement) -> Vec<&'a str> {
        self.entity_groups
            .get(&(element.dim, element.entity))
            .into_iter()
            .flatten()
            .filter_map(|t| self.group_names.get(&(element.dim, *t)))
            .map(|s| s.as_str())
            .collect()
    }
}

/// Nodes per element of the Gmsh types read here; None for others.
pub fn nodes_per_element(kind: i32) -> Option<usize> {
    match kind {
        15 => Some(1),
        1 => Some(2),
        8 => Some(3),
        2 => Some(3),
        9 => Some(6),
        3 => Some(4),
        16 => Some(8),
        10 => Some(9),
        _ => None,
    }
}

/// Read `path` (format 4.1, ASCII or binary).
pub fn read(path: &Path) -> Result<GmshMesh, GmshError> {
    let bytes = std::fs::read(path).map_err(|source| GmshError::Io {
        path: path.display().to_string(),
        source,
    })?;
    parse(&bytes)
}

/// Parse the bytes of a `.msh` file (format 4.1, ASCII or binary).
pub fn parse(bytes: &[u8]) -> Result<GmshMesh, GmshError> {
    let mut cursor = Cursor {
        bytes,
        at: 0,
        binary: false,
        section: String::new(),
    };
    let mut mesh = GmshMesh::default();
    let mut seen_format = false;
    while let Some(header) = cursor.next_header() {
        cursor.section = header.clone();
        match header.as_str() {
            "MeshFormat" => {
                read_format(&mut cursor)?;
                seen_format = true;
            }
            _ if !seen_format => {
                return Err(cursor.malformed("the file does not start with $MeshFormat"))
            }
            "PhysicalNames" => read_names(&mut cursor, &mut mesh)?,
            "Entities" => read_entities(&mut cursor, &mut mesh)?,
            "PartitionedEntities" => {
                return Err(cursor.malformed(
                    "a partitioned mesh: write it unpartitioned (Mesh.PartitionSplitMeshFiles = 0, no partitioning)",
                ))
            }
            "Nodes" => read_nodes(&mut cursor, &mut mesh)?,
            "Elements" => read_elements(&mut cursor, &mut mesh)?,
            _ => {
                cursor.skip_to_end(&header)?;
                continue;
            }
        }
        cursor.expect_end(&header)?;
    }
    if !seen_format {
        return Err(GmshError::Malformed {
            section: "MeshFormat".into(),
            what: "not a Gmsh mesh file (no $MeshFormat)".into(),
        });
    }
    Ok(mesh)
}

/// A position in the file and how its numbers are written.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
    binary: bool,
    section: String,
}

impl Cursor<'_> {
    fn malformed(&self, what: impl Into<String>) -> GmshError {
        GmshError::Malformed {
            section: self.section.clone(),
            what: what.into(),
        }
    }

    /// The next line, without its line end.
    fn line(&mut self) -> Option<&str> {
        if self.at >= self.bytes.len() {
            return None;
        }
        let rest = &self.bytes[self.at..];
        let end = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        self.at += (end + 1).min(rest.len());
        std::str::from_utf8(&rest[..end])
            .ok()
            .map(|s| s.trim_end_matches('\r'))
    }

    /// The next `$Name` header's name, skipping blank lines.
    fn next_header(&mut self) -> Option<String> {
        loop {
            let line = self.line()?.trim().to_string();
            if line.is_empty() {
                continue;
            }
            return line.strip_prefix('$').map(str::to_string);
        }
    }

    fn expect_end(&mut self, section: &str) -> Result<(), GmshError> {
        let end = format!("$End{section}");
        loop {
            match self.line().map(str::trim) {
                Some("") => continue,
                Some(l) if l == end => return Ok(()),
                Some(l) => {
                    let l = l.chars().take(40).collect::<String>();
                    return Err(self.malformed(format!("expected {end}, found \"{l}\"")));
                }
                None => return Err(self.malformed(format!("the file ends before {end}"))),
            }
        }
    }

    fn skip_to_end(&mut self, section: &str) -> Result<(), GmshError> {
        let end = format!("\n$End{section}");
        let rest = &self.bytes[self.at.saturating_sub(1)..];
        match rest.windows(end.len()).position(|w| w == end.as_bytes()) {
            Some(p) => {
                self.at = self.at.saturating_sub(1) + p + 1;
                self.line();
                Ok(())
            }
            None => Err(self.malformed(format!("the file ends before $End{section}"))),
        }
    }

    /// The next whitespace-separated token (ASCII).
    fn token(&mut self) -> Result<&str, GmshError> {
        while self.at < self.bytes.len() && self.bytes[self.at].is_ascii_whitespace() {
            self.at += 1;
        }
        let start = self.at;
        while self.at < self.bytes.len() && !self.bytes[self.at].is_ascii_whitespace() {
            self.at += 1;
        }
        if start == self.at {
            return Err(self.malformed("the file ends inside the section"));
        }
        std::str::from_utf8(&self.bytes[start..self.at])
            .map_err(|_| self.malformed("a value is not text"))
    }

    fn take<const N: usize>(&mut self) -> Result<[u8; N], GmshError> {
        let slice = self
            .bytes
            .get(self.at..self.at + N)
            .ok_or_else(|| self.malformed("the file ends inside the section"))?;
        self.at += N;
        Ok(slice.try_into().expect("N bytes"))
    }

    fn int(&mut self) -> Result<i32, GmshError> {
        if self.binary {
            return Ok(i32::from_le_bytes(self.take()?));
        }
        let t = self.token()?.to_string();
        t.parse()
            .map_err(|_| self.malformed(format!("\"{t}\" is not an integer")))
    }

    fn size(&mut self) -> Result<usize, GmshError> {
        if self.binary {
            return usize::try_from(u64::from_le_bytes(self.take()?))
                .map_err(|_| self.malformed("a count beyond this machine's memory"));
        }
        let t = self.token()?.to_string();
        t.parse()
            .map_err(|_| self.malformed(format!("\"{t}\" is not a count")))
    }

    fn double(&mut self) -> Result<f64, GmshError> {
        let value = if self.binary {
            f64::from_le_bytes(self.take()?)
        } else {
            let t = self.token()?.to_string();
            t.parse()
                .map_err(|_| self.malformed(format!("\"{t}\" is not a number")))?
        };
        if value.is_finite() {
            Ok(value)
        } else {
            Err(self.malformed(format!("a coordinate is {value}")))
        }
    }

    /// A count that cannot exceed what is left of the file (each entry takes `bytes` bytes
    /// in binary, at least 2 characters in ASCII): a corrupt count fails here rather than
    /// asking for terabytes.
    fn count(&mut self, bytes: usize) -> Result<usize, GmshError> {
        let n = self.size()?;
        let least = if self.binary { bytes } else { 2 };
        if n.saturating_mul(least) > self.bytes.len() - self.at.min(self.bytes.len()) {
            return Err(self.malformed(format!("a count of {n} is more than the file holds")));
        }
        Ok(n)
    }
}

fn read_format(cursor: &mut Cursor) -> Result<(), GmshError> {
    let Some(line) = cursor.line().map(str::to_string) else {
        return Err(cursor.malformed("empty"));
    };
    let fields: Vec<&str> = line.split_whitespace().collect();
    let version = fields.first().copied().unwrap_or("").to_string();
    if version != "4.1" {
        return Err(GmshError::Version { version });
    }
    cursor.binary = fields.get(1) == Some(&"1");
    if fields.get(2) != Some(&"8") {
        return Err(cursor.malformed(format!(
            "size_t of {} bytes; wearfem reads files with 8",
            fields.get(2).unwrap_or(&"?")
        )));
    }
    if cursor.binary {
        if cursor.take::<4>()? != 1i32.to_le_bytes() {
            return Err(
                cursor.malformed("a big-endian binary file: write it as ASCII (Mesh.Binary = 0)")
            );
        }
        cursor.line();
    }
    Ok(())
}

fn read_names(cursor: &mut Cursor, mesh: &mut GmshMesh) -> Result<(), GmshError> {
    // Always ASCII, one group per line: dim tag "name".
    let Some(n) = cursor.line().and_then(|l| l.trim().parse::<usize>().ok()) else {
        return Err(cursor.malformed("no count of names"));
    };
    for _ in 0..n {
        let Some(line) = cursor.line().map(str::to_string) else {
            return Err(cursor.malformed("fewer names than counted"));
        };
        let mut parts = line.splitn(3, char::is_whitespace);
        let dim = parts.next().and_then(|s| s.parse().ok());
        let tag = parts.next().and_then(|s| s.parse().ok());
        let name = parts.next().map(|s| s.trim().trim_matches('"').to_string());
        match (dim, tag, name) {
            (Some(d), Some(t), Some(name)) => {
                mesh.group_names.insert((d, t), name);
            }
            _ => return Err(cursor.malformed(format!("cannot read the name line \"{line}\""))),
        }
    }
    Ok(())
}

fn read_entities(cursor: &mut Cursor, mesh: &mut GmshMesh) -> Result<(), GmshError> {
    let counts = [
        cursor.size()?,
        cursor.size()?,
        cursor.size()?,
        cursor.size()?,
    ];
    for (dim, &count) in counts.iter().enumerate() {
        for _ in 0..count {
            let tag = cursor.int()?;
            // A point has its coordinates, the others their bounding box.
            let doubles = if dim == 0 { 3 } else { 6 };
            for _ in 0..doubles {
                cursor.double()?;
            }
            let n = cursor.count(4)?;
            let groups = (0..n)
                .map(|_| cursor.int())
                .collect::<Result<Vec<_>, _>>()?;
            if dim > 0 {
                let bounding = cursor.count(4)?;
                for _ in 0..bounding {
                    cursor.int()?;
                }
            }
            mesh.entity_groups.insert((dim as i32, tag), groups);
        }
    }
    Ok(())
}

fn read_nodes(cursor: &mut Cursor, mesh: &mut GmshMesh) -> Result<(), GmshError> {
    let blocks = cursor.count(20)?;
    let _total = cursor.size()?;
    let (_min, _max) = (cursor.size()?, cursor.size()?);
    for _ in 0..blocks {
        let dim = cursor.int()?;
        let _entity = cursor.int()?;
        let parametric = cursor.int()?;
        let n = cursor.count(32)?;
        let tags = (0..n)
            .map(|_| cursor.size())
            .collect::<Result<Vec<_>, _>>()?;
        let extra = if parametric != 0 {
            dim.max(0) as usize
        } else {
            0
        };
        for tag in tags {
            let (x, y, _z) = (cursor.double()?, cursor.double()?, cursor.double()?);
            for _ in 0..extra {
                cursor.double()?;
            }
            mesh.nodes.insert(tag, [x, y]);
        }
    }
    Ok(())
}

fn read_elements(cursor: &mut Cursor, mesh: &mut GmshMesh) -> Result<(), GmshError> {
    let blocks = cursor.count(20)?;
    let _total = cursor.size()?;
    let (_min, _max) = (cursor.size()?, cursor.size()?);
    for _ in 0..blocks {
        let dim = cursor.int()?;
        let entity = cursor.int()?;
        let kind = cursor.int()?;
        let n = cursor.count(16)?;
        let Some(per) = nodes_per_element(kind) else {
            let tag = cursor.size()?;
            return Err(GmshError::UnknownType { tag, kind });
        };
        let kind_dim = match kind {
            15 => 0,
            1 | 8 => 1,
            _ => 2,
        };
        if kind_dim != dim {
            return Err(cursor.malformed(format!(
                "elements of Gmsh type {kind} (dimension {kind_dim}) in a block of entity dimension {dim}"
            )));
        }
        for _ in 0..n {
            let tag = cursor.size()?;
            let nodes = (0..per)
                .map(|_| cursor.size())
                .collect::<Result<Vec<_>, _>>()?;
            if dim >= 1 {
                mesh.elements.push(GmshElement {
                    tag,
                    kind,
                    dim,
                    entity,
                    nodes,
                });
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: &str = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 5 \"bottom\"\n2 7 \"plate\"\n$EndPhysicalNames\n$Entities\n0 1 1 0\n1 0 0 0 1 0 0 1 5 2 1 -2\n1 0 0 0 1 1 0 1 7 4 1 2 3 4\n$EndEntities\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n$Elements\n2 2 1 2\n1 1 1 1\n1 1 2\n2 1 3 1\n2 1 2 3 4\n$EndElements\n";

    #[test]
    fn an_ascii_square_gives_its_nodes_elements_and_groups() {
        let mesh = parse(SQUARE.as_bytes()).unwrap();
        assert_eq!(mesh.nodes.len(), 4);
        assert_eq!(mesh.nodes[&3], [1.0, 1.0]);
        assert_eq!(mesh.elements.len(), 2);
        let quad = &mesh.elements[1];
        assert_eq!((quad.kind, quad.nodes.clone()), (3, vec![1, 2, 3, 4]));
        assert_eq!(mesh.element_groups(quad), vec!["plate"]);
        assert_eq!(mesh.element_groups(&mesh.elements[0]), vec!["bottom"]);
        assert_eq!(mesh.groups(1)["bottom"], 5);
    }

    #[test]
    fn other_versions_and_truncated_files_are_refused() {
        let old = SQUARE.replace("4.1 0 8", "2.2 0 8");
        assert!(matches!(
            parse(old.as_bytes()),
            Err(GmshError::Version { .. })
        ));
        let cut = &SQUARE[..SQUARE.find("$EndNodes").unwrap() - 4];
        assert!(matches!(
            parse(cut.as_bytes()),
            Err(GmshError::Malformed { .. })
        ));
        // A point element in a curve's block (a review's hand-made file panicked later on).
        let point_in_curve = SQUARE.replace("1 1 1 1\n1 1 2", "1 1 15 1\n1 1");
        assert!(matches!(
            parse(point_in_curve.as_bytes()),
            Err(GmshError::Malformed { .. })
        ));
        let triangle_line = SQUARE.replace("1 1 1 1\n1 1 2", "1 1 99 1\n1 1 2");
        assert!(matches!(
            parse(triangle_line.as_bytes()),
            Err(GmshError::UnknownType { kind: 99, .. })
        ));
    }
}
