//! The human-readable results of the `ccd-exact` binary: a pair's timeline
//! and contacts, and a world's broad phase, colliding pairs and first
//! contact.

use ccd_exact::{Arithmetic, Geometry, Options, Outcome, WorldOutcome};
use std::fmt::Write as _;

/// The human-readable result: the timeline, the contacts, and in words
/// what is proven and what is not (`float`: the float mode ran, so nothing
/// is).
pub fn pair(out: &Outcome, options: &Options) -> String {
    let float = options.arithmetic == Arithmetic::Float;
    let s = &out.stats;
    let mut t = String::new();
    if s.path == ccd_exact::Path::Interval {
        let _ = writeln!(
            t,
            "span [{}, {}]; non-rational motion: certified interval enclosures ({})\n",
            out.span[0],
            out.span[1],
            s.branch_name()
        );
    } else {
        let sr0 = s.deg_sr0.map_or("≡ 0".into(), |d| d.to_string());
        let _ = writeln!(
            t,
            "span [{}, {}]; deg_t f = {}, deg sr0 = {sr0}, branch: {}\n",
            out.span[0],
            out.span[1],
            s.deg_f,
            s.branch_name()
        );
    }
    let _ = writeln!(t, "  {:<9} {:>20}  {:>20}", "state", "from", "to");
    let unproven = |ok: bool| if ok || float { "" } else { "  (not proven)" };
    let mut gaps = out.gaps.iter().peekable();
    let gap_line = |t: &mut String, g: &ccd_exact::Gap| {
        let _ = writeln!(
            t,
            "  {:<9} {:>20}  {:>20}  (not covered: {})",
            "undecided",
            g.lo.to_decimal(12),
            g.hi.to_decimal(12),
            g.reason
        );
        if let Some(w) = &g.witness {
            let _ = writeln!(t, "  {:<9} proven {} at t = {}", "", w.state.name(), w.t);
        }
    };
    let show = |b: &ccd_exact::Box3| b.approx(12).join(", ");
    // The point and normal at one end of a touch segment, or one contact.
    let geometry_lines = |t: &mut String, indent: &str, g: &Geometry| match g {
        Geometry::Point {
            point,
            normal,
            certified,
        } => {
            let mark = if *certified { "" } else { "  (NOT certified)" };
            let _ = writeln!(
                t,
                "{indent}point  ≈ ({}){mark}  (box width {:.1e})\n{indent}normal ≈ ({})  (A's outward normal, largest component ±1)",
                show(point),
                point.width().to_f64(),
                show(normal)
            );
        }
        Geometry::NotASinglePoint => {
            let _ = writeln!(t, "{indent}point: not a single point");
        }
        Geometry::Unknown { reason } => {
            let _ = writeln!(t, "{indent}point: not computed ({reason})");
        }
    };
    for (k, seg) in out.timeline.iter().enumerate() {
        while let Some(g) = gaps.next_if(|g| g.hi <= seg.start.lo) {
            gap_line(&mut t, g);
        }
        let _ = writeln!(
            t,
            "  {:<9} {:>20}  {:>20}{}",
            seg.state.name(),
            seg.start.approx(12),
            seg.end.approx(12),
            unproven(seg.certified)
        );
        if let Some(Some([start, end])) = out.segment_geometry.get(k) {
            t.push_str("            at the start:\n");
            geometry_lines(&mut t, "              ", start);
            if seg.start != seg.end {
                t.push_str("            at the end:\n");
                geometry_lines(&mut t, "              ", end);
            }
        }
    }
    for g in gaps {
        gap_line(&mut t, g);
    }
    t.push('\n');
    if out.contacts.is_empty() {
        t.push_str("contacts: none\n");
    }
    for (k, c) in out.contacts.iter().enumerate() {
        let mark = if c.certified { "" } else { "  (NOT certified)" };
        let _ = writeln!(
            t,
            "contact {} ≈ {}{mark}\n    lo = {}\n    hi = {}",
            k + 1,
            c.approx(15),
            c.lo,
            c.hi
        );
        if let Some(g) = out.geometry.get(k) {
            geometry_lines(&mut t, "    ", g);
        }
    }
    match (&out.first_contact, &out.undecided) {
        (Some(fc), _) => {
            let mark = unproven(fc.certified);
            let _ = writeln!(t, "first contact ≈ {}{mark}", fc.approx(15));
        }
        (None, _) if out.collision_free => t.push_str("collision-free over the span\n"),
        _ => {}
    }
    if let Some(why) = &out.undecided {
        let _ = writeln!(
            t,
            "collision-free: NOT decided (neither separation over the span nor a collision is proven: {why})"
        );
    } else if !float && !out.collision_free && !out.certified() {
        t.push_str("a collision is proven (a certified touch or overlap)\n");
    }
    if !out.gaps.is_empty() {
        let _ = writeln!(
            t,
            "timeline NOT complete: {} piece(s) of the span undecided within the effort budget",
            out.gaps.len()
        );
    } else if options.first_contact_only && !out.complete {
        t.push_str("(first contact only: the timeline stops there)\n");
    }
    if float {
        if !out.certified() {
            t.push_str(
                "NOT certified: float arithmetic (run with --arithmetic exact for proven answers)\n",
            );
        }
    } else if !out.certified() {
        let counts = [
            (
                out.timeline.iter().filter(|s| !s.certified).count(),
                "segment state(s) not proven",
            ),
            (
                out.contacts.iter().filter(|c| !c.certified).count(),
                "contact(s) not certified",
            ),
            (out.gaps.len(), "piece(s) of the span undecided"),
        ];
        let what: Vec<String> = counts
            .iter()
            .filter(|(n, _)| *n > 0)
            .map(|(n, what)| format!("{n} {what}"))
            .collect();
        let _ = writeln!(t, "NOT everything is proven: {}", what.join(", "));
    }
    t
}

/// A world's result: the broad phase's counts, each colliding pair with its
/// contacts, the undecided pairs, and the world's first contact.
pub fn world(w: &WorldOutcome, options: &Options) -> String {
    let mut t = String::new();
    let n = w.bodies.len() as u64;
    let b = &w.broad_phase;
    let _ = writeln!(
        t,
        "world: {n} bodies over span [{}, {}]\nbroad phase: {} pairs, {} candidate(s), {} proven separate by certified boxes and separating planes ({} slices of the span; boxes alone: {} candidates)\n",
        w.span[0],
        w.span[1],
        n * n.saturating_sub(1) / 2,
        b.candidates,
        b.pruned,
        b.slices,
        b.box_overlaps
    );
    let name = |i: usize| w.bodies[i].as_str();
    let colliding: Vec<_> = w.pairs.iter().filter(|p| p.colliding()).collect();
    let _ = writeln!(t, "colliding pairs: {}", colliding.len());
    for p in &colliding {
        let Ok(o) = &p.result else { continue };
        let states: Vec<&str> = o.timeline.iter().map(|s| s.state.name()).collect();
        let contacts: Vec<String> = o.contacts.iter().map(|c| c.approx(12)).collect();
        let first = o
            .first_contact
            .as_ref()
            .map_or("-".into(), |c| c.approx(12));
        let _ = writeln!(
            t,
            "  {} × {}: first contact ≈ {first}; {}{}",
            name(p.a),
            name(p.b),
            states.join(" → "),
            if contacts.is_empty() {
                String::new()
            } else {
                format!("; contacts ≈ {}", contacts.join(", "))
            }
        );
    }
    let separate = w
        .pairs
        .iter()
        .filter(|p| !p.colliding() && !p.undecided())
        .count();
    let _ = writeln!(
        t,
        "candidates proven separate by the exact query: {separate}"
    );
    let undecided: Vec<_> = w.pairs.iter().filter(|p| p.undecided()).collect();
    if !undecided.is_empty() {
        let _ = writeln!(t, "undecided pairs: {}", undecided.len());
        for p in undecided {
            let why = match &p.result {
                Ok(o) => o.undecided.clone().unwrap_or_default(),
                Err(e) => e.to_string(),
            };
            let _ = writeln!(t, "  {} × {}: {why}", name(p.a), name(p.b));
        }
    }
    t.push('\n');
    match &w.first_contact {
        Some(c) => {
            let mark = if c.instant.certified || options.arithmetic == Arithmetic::Float {
                ""
            } else {
                "  (NOT certified)"
            };
            let _ = writeln!(
                t,
                "first contact in the world ≈ {}{mark}: {} × {}\n    lo = {}\n    hi = {}",
                c.instant.approx(15),
                name(c.pair.0),
                name(c.pair.1),
                c.instant.lo,
                c.instant.hi
            );
        }
        None if w.complete && w.undecided().is_empty() => {
            t.push_str("no contact in the world over the span\n");
        }
        None => t.push_str("no contact found\n"),
    }
    if !w.complete {
        let _ = writeln!(
            t,
            "(first contact only: {} of {} candidate pairs queried, each up to its first contact; no other can touch earlier)",
            w.pairs.len(),
            b.candidates
        );
    }
    if options.arithmetic == Arithmetic::Float {
        t.push_str(
            "NOT certified: float arithmetic (run with --arithmetic exact for proven answers)\n",
        );
    } else if !w.certified() {
        t.push_str("NOT everything is proven (see the pairs above, or --json)\n");
    }
    t
}
