//! Contact islands: the contacts that are coupled through shared dynamic
//! bodies. Static bodies (and the world) couple nothing, so a stack of boxes
//! on the ground is one island but two balls on the same ground are two.
//! Each island's LCP is independent of the others: solving them one by one
//! gives the solution of the whole scene's LCP, whose M is block-diagonal
//! under this partition.

use crate::scene::Scene;

/// The contacts of one island, in increasing index order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Island {
    pub contacts: Vec<usize>,
}

impl Island {
    /// Number of contacts (the LCP dimension n).
    pub fn len(&self) -> usize {
        self.contacts.len()
    }
}

/// One island of a scene and its LCP, as the solvers see it.
#[derive(Clone, Debug, PartialEq)]
pub struct IslandProblem {
    /// The scene's contact indices, in the order of the LCP's rows.
    pub contacts: Vec<usize>,
    /// The island's (M, q): M = J M⁻¹ Jᵀ over its contacts, q the approach
    /// velocities with restitution.
    pub lcp: crate::lcp::Lcp,
}

impl Scene {
    /// Checks the scene (errors name `item`, e.g. "scene 3", with the
    /// contact or body and the field) and returns its islands with their
    /// LCPs, assembled in f64: what [`crate::Solver::solve_scenes`] solves.
    pub(crate) fn islands(&self, item: &str) -> Result<Vec<IslandProblem>, crate::Error> {
        self.validate(item)?;
        let built = crate::build::Built::new(self);
        Ok(built
            .islands
            .into_iter()
            .zip(built.lcps)
            .map(|(isl, lcp)| IslandProblem {
                contacts: isl.contacts,
                lcp,
            })
            .collect())
    }
}

fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// Partitions the contacts of a validated scene into islands, ordered by
/// their first contact. Every contact has at least one dynamic body (the
/// scene checks enforce it).
pub fn find_islands(scene: &Scene) -> Vec<Island> {
    let nb = scene.bodies.len();
    let dynamic: Vec<bool> = scene.bodies.iter().map(|b| !b.is_static()).collect();
    let mut parent: Vec<usize> = (0..nb).collect();
    for c in &scene.contacts {
        if let Some(b) = c.b {
            if dynamic[c.a] && dynamic[b] {
                let (ra, rb) = (find(&mut parent, c.a), find(&mut parent, b));
                parent[ra.max(rb)] = ra.min(rb);
            }
        }
    }
    // Island of a contact: the root of its dynamic body.
    let mut island_of_root = vec![usize::MAX; nb];
    let mut islands: Vec<Island> = Vec::new();
    for (k, c) in scene.contacts.iter().enumerate() {
        let body = if dynamic[c.a] {
            c.a
        } else {
            c.b.expect("validated: a dynamic body exists")
        };
        let root = find(&mut parent, body);
        if island_of_root[root] == usize::MAX {
            island_of_root[root] = islands.len();
            islands.push(Island {
                contacts: Vec::new(),
            });
        }
        islands[island_of_root[root]].contacts.push(k);
    }
    islands
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Body, Contact};

    fn contact(a: usize, b: Option<usize>) -> Contact {
        Contact {
            a,
            b,
            point: [0.0; 3],
            normal: [0.0, 1.0, 0.0],
            restitution: 0.0,
            id: None,
            bias: 0.0,
            friction: 0.0,
            tangent: None,
        }
    }

    #[test]
    fn static_bodies_couple_nothing() {
        let ball = Body::new(1.0, [1.0; 3], [0.0; 3]);
        let scene = Scene {
            bodies: vec![Body::fixed([0.0; 3]), ball.clone(), ball.clone(), ball],
            // 1 and 2 both touch the ground (body 0) and the world; 3 sits on 2.
            contacts: vec![
                contact(1, Some(0)),
                contact(2, Some(0)),
                contact(1, None),
                contact(3, Some(2)),
            ],
        };
        let islands = find_islands(&scene);
        assert_eq!(
            islands,
            vec![
                Island {
                    contacts: vec![0, 2]
                },
                Island {
                    contacts: vec![1, 3]
                }
            ]
        );
    }
}
