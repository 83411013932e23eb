//! What the timing examples (`speed`, `interference`) share: their
//! command-line flags and medians.

/// Removes `--flag N` from `args` and returns `N` (at least 1); `default`
/// when the flag is absent or `N` is not a count. A flag right after it
/// (`--reps --no-geometry`) is left in place.
pub fn take_count(args: &mut Vec<String>, flag: &str, default: usize) -> usize {
    let Some(i) = args.iter().position(|a| a == flag) else {
        return default;
    };
    let next = args.get(i + 1).filter(|s| !s.starts_with("--"));
    let n = next.and_then(|s| s.parse().ok()).unwrap_or(default).max(1);
    let end = if next.is_some() { i + 2 } else { i + 1 };
    args.drain(i..end);
    n
}

/// Removes the switch `flag` from `args`: whether it was given.
pub fn take_switch(args: &mut Vec<String>, flag: &str) -> bool {
    let at = args.iter().position(|a| a == flag);
    if let Some(i) = at {
        args.remove(i);
    }
    at.is_some()
}

/// The median of `v` (the upper middle one of an even count).
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The pair scenes named by `paths`, each with its path: unreadable files
/// are reported and skipped, world files and bad scenes skipped.
pub fn scenes(paths: Vec<String>) -> impl Iterator<Item = (String, ccd_exact::Scene)> {
    paths.into_iter().filter_map(|path| {
        let Ok(text) = std::fs::read_to_string(&path) else {
            eprintln!("{path}: unreadable");
            return None;
        };
        let scene = ccd_exact::Scene::from_toml(&text).ok()?; // a world file or a bad scene
        Some((path, scene))
    })
}
