//! What one step of the history changed, in the user's words: "light 0 removed", "Material
//! shininess 25.6 ➡ 100" ("luz 0 removida", "Material: brilho (ns) 25,6 ➡ 100" in
//! Portuguese). Worked out from the two documents each time it is shown, so it is in the
//! window's language of the moment, and a light added or removed is named as such rather
//! than as the fields that shifted when the list closed up ("light 0 ambient and 9 more").

use phonglab_core::explain::fmt_sig;
use phonglab_core::{Document, Light};

use crate::t;

/// The fields that differ between two documents, as their scene files name them
/// (`material.shininess`, `lights.0.position`): what joins a drag's steps into one.
pub fn changed_fields(before: &Document, after: &Document) -> Vec<String> {
    changes(before, after).into_iter().map(|(k, ..)| k).collect()
}

/// What changed from `before` to `after`, for people, in the current language: a light
/// added or removed; one field with its two values; or the first field and how many more.
pub fn label(before: &Document, after: &Document) -> String {
    if let Some(said) = light_added_or_removed(&before.scene.lights, &after.scene.lights) {
        return said;
    }
    let changed = changes(before, after);
    match changed.as_slice() {
        [] => t!("history-no-change"),
        [(k, x, y)] => {
            let (from, to) = match enum_values(k, before, after) {
                Some(pair) => pair,
                None => (value_for_people(x.as_deref()), value_for_people(y.as_deref())),
            };
            format!("{} {from} ➡ {to}", field_name(k))
        }
        [(k, ..), rest @ ..] => t!("history-and-more", field = field_name(k), count = rest.len()),
    }
}

/// "light 1 added" or "light 0 removed" when `after` is `before` with one light more or
/// less (the lights after it moved up or down one place).
fn light_added_or_removed(before: &[Light], after: &[Light]) -> Option<String> {
    let (longer, shorter, added) = match before.len().checked_sub(after.len()) {
        Some(1) => (before, after, false),
        None if after.len() == before.len() + 1 => (after, before, true),
        _ => return None,
    };
    let i = (0..shorter.len()).find(|&i| longer[i] != shorter[i]).unwrap_or(shorter.len());
    if longer[i + 1..] != shorter[i..] {
        return None;
    }
    let index = i.to_string();
    Some(if added { t!("history-light-added", index = index) } else { t!("history-light-removed", index = index) })
}

/// Every changed field: (dotted path, value before, value after), in the scene file's order.
fn changes(before: &Document, after: &Document) -> Vec<(String, Option<String>, Option<String>)> {
    let (mut a, mut b) = (leaves(before), leaves(after));
    // A change of preset says so alone; a preset edited into a custom material says which
    // field was edited (the preset's name going is not the change).
    let preset = |l: &[(String, String)]| l.iter().find(|(k, _)| k == "material.preset").map(|(_, v)| v.clone());
    let (pa, pb) = (preset(&a), preset(&b));
    if pa != pb && pa.as_deref() != Some("custom") && pb.as_deref() != Some("custom") {
        a.retain(|(k, _)| !k.starts_with("material.") || k == "material.preset");
        b.retain(|(k, _)| !k.starts_with("material.") || k == "material.preset");
    } else {
        a.retain(|(k, _)| k != "material.preset");
        b.retain(|(k, _)| k != "material.preset");
    }
    // Every field of either, once, in the order the scene files give them.
    let mut seen = std::collections::HashSet::new();
    let keys: Vec<&String> = a.iter().chain(&b).map(|(k, _)| k).filter(|k| seen.insert(*k)).collect();
    let find = |list: &[(String, String)], k: &str| list.iter().find(|(x, _)| x == k).map(|(_, v)| v.clone());
    keys.into_iter().map(|k| (k.clone(), find(&a, k), find(&b, k))).filter(|(_, x, y)| x != y).collect()
}

/// Every field of `d` as (dotted path, value text): its scene file's, with the material's
/// own values in place of a preset's name (and the preset, or "custom", as
/// `material.preset`).
fn leaves(d: &Document) -> Vec<(String, String)> {
    let mut out = Vec::new();
    if let Some(mut t) = d.to_toml().ok().and_then(|t| t.parse::<toml::Table>().ok()) {
        t.remove("material");
        flatten("", &toml::Value::Table(t), &mut out);
    }
    let m = &d.scene.material;
    let rgba = |c: glam::DVec4| format!("[{}]", c.to_array().map(|x| fmt_sig(x, 6)).join(" "));
    out.push(("material.preset".into(), phonglab_core::materials::name_of(m).unwrap_or("custom").into()));
    out.push(("material.ambient".into(), rgba(m.ambient)));
    out.push(("material.diffuse".into(), rgba(m.diffuse)));
    out.push(("material.specular".into(), rgba(m.specular)));
    out.push(("material.emission".into(), rgba(m.emission)));
    out.push(("material.shininess".into(), fmt_sig(m.shininess, 6)));
    out
}

/// A field's name for people: the catalogue's `history-field`, chosen by the path with a
/// light's number taken out (`lights.0.spot_cutoff` is `light-spot_cutoff` of light 0), and
/// the camera, the back material and the colour material each named whole.
fn field_name(key: &str) -> String {
    const WHOLE: [&str; 4] = ["view.camera", "camera", "back_material", "color_material"];
    let mut parts = key.split('.');
    let (field, index) = match (parts.next(), parts.next(), parts.next()) {
        (Some("lights"), Some(i), Some(field)) => (format!("light-{field}"), i.to_string()),
        _ => {
            let whole =
                WHOLE.into_iter().find(|g| key.strip_prefix(g).is_some_and(|r| r.is_empty() || r.starts_with('.')));
            (whole.unwrap_or(key).replace('.', "-"), String::new())
        }
    };
    t!("history-field", field = field, index = index)
}

/// A value as the scene file writes it, for people: numbers with the language's decimal
/// mark, switches on or off, nothing as "(none)".
fn value_for_people(v: Option<&str>) -> String {
    match v {
        None => t!("history-none"),
        Some("on") => t!("history-on"),
        Some("off") => t!("history-off"),
        Some(text) => crate::locale::decimal(text),
    }
}

/// The object and the shading, named as the top bar names them.
fn enum_values(key: &str, before: &Document, after: &Document) -> Option<(String, String)> {
    match key {
        "view.object" => Some((before.view.object.label(), after.view.object.label())),
        "view.shading" => Some((before.view.shading.label().to_string(), after.view.shading.label().to_string())),
        _ => None,
    }
}

/// Every leaf of `v` as (dotted path, value text); arrays of numbers are one leaf.
fn flatten(path: &str, v: &toml::Value, out: &mut Vec<(String, String)>) {
    let join = |k: &str| if path.is_empty() { k.to_string() } else { format!("{path}.{k}") };
    match v {
        toml::Value::Table(t) => t.iter().for_each(|(k, v)| flatten(&join(k), v, out)),
        toml::Value::Array(items) if items.iter().any(toml::Value::is_table) => {
            items.iter().enumerate().for_each(|(i, v)| flatten(&join(&i.to_string()), v, out));
        }
        toml::Value::Array(items) => {
            let parts: Vec<String> = items.iter().map(value_text).collect();
            out.push((path.to_string(), format!("[{}]", parts.join(" "))));
        }
        other => out.push((path.to_string(), value_text(other))),
    }
}

fn value_text(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(x) => fmt_sig(*x, 6),
        toml::Value::Integer(i) => i.to_string(),
        toml::Value::String(s) => s.clone(),
        toml::Value::Boolean(b) => if *b { "on" } else { "off" }.to_string(),
        toml::Value::Array(items) => format!("[{}]", items.iter().map(value_text).collect::<Vec<_>>().join(" ")),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::locale::{Lang, Locale, set_thread};

    fn with_shininess(s: f64) -> Document {
        let mut d = Document::default();
        d.scene.material.shininess = s;
        d
    }

    fn in_lang(lang: Lang, f: impl FnOnce() -> String) -> String {
        set_thread(Some(Locale { lang, decimal: lang.decimal_mark() }));
        let s = f();
        set_thread(None);
        s
    }

    #[test]
    fn a_step_is_labelled_with_its_field_and_values() {
        let (a, b) = (with_shininess(25.6), with_shininess(100.0));
        assert_eq!(changed_fields(&a, &b), ["material.shininess"]);
        assert_eq!(in_lang(Lang::En, || label(&a, &b)), "Material shininess 25.6 ➡ 100");
        assert_eq!(in_lang(Lang::PtPt, || label(&a, &b)), "Material: brilho (ns) 25,6 ➡ 100");
        let mut d = Document::default();
        d.scene.lights[0].position.z = 300.5;
        // (Documents made outside `in_lang`: the worksheet's name is in the language.)
        let start = Document::default();
        let said = in_lang(Lang::PtBr, || label(&start, &d));
        assert!(said.starts_with("luz 0: posição [") && said.ends_with("300,5 1]"), "{said}");
        // A preset chosen is named; a switch is on or off in the language.
        let mut gold = Document::default();
        gold.scene.material = phonglab_core::materials::by_name("gold").unwrap().clone();
        assert_eq!(in_lang(Lang::En, || label(&start, &gold)), "material bronze ➡ gold");
        let mut local = Document::default();
        local.scene.light_model.local_viewer = true;
        assert_eq!(in_lang(Lang::PtPt, || label(&start, &local)), "Observador local desligado ➡ ligado");
        let mut teapot = Document::default();
        teapot.view.object = phonglab_core::ObjectKind::Sphere;
        assert_eq!(in_lang(Lang::PtPt, || label(&start, &teapot)), "objeto Bule ➡ Esfera");
    }

    #[test]
    fn a_light_removed_or_added_is_named_so_in_the_users_language() {
        let two = {
            let mut d = Document::default();
            let mut l = d.scene.lights[0].clone();
            l.position.x = 7.0;
            d.scene.lights.push(l);
            d
        };
        let mut first_gone = two.clone();
        first_gone.scene.lights.remove(0);
        // Many fields of light 0 differ (light 1 took its place): it is still one light gone.
        assert!(changed_fields(&two, &first_gone).len() > 1);
        assert_eq!(in_lang(Lang::PtPt, || label(&two, &first_gone)), "luz 0 removida");
        assert_eq!(in_lang(Lang::En, || label(&two, &first_gone)), "light 0 removed");
        assert_eq!(in_lang(Lang::PtBr, || label(&first_gone, &two)), "luz 0 adicionada");
        let start = Document::default();
        assert_eq!(in_lang(Lang::PtPt, || label(&start, &two)), "luz 1 acrescentada");
        // Several fields at once: the first, and how many more, in the language.
        let mut many = Document::default();
        many.scene.material.shininess = 3.0;
        many.scene.light_model.local_viewer = true;
        let said = in_lang(Lang::PtPt, || label(&start, &many));
        assert_eq!(said, "Observador local e mais 1");
    }

    #[test]
    fn every_field_of_the_shipped_scenes_has_a_name_in_every_language() {
        let mut docs: Vec<Document> = phonglab_core::library::documents().into_iter().map(|(_, d)| d).collect();
        docs.extend(crate::io::scenes::scene_files().iter().map(|f| f.doc.clone()));
        for lang in Lang::ALL {
            let unnamed = in_lang(lang, || {
                let other = t!("history-field", field = "none of them", index = "");
                let mut bad: Vec<String> =
                    docs.iter().flat_map(leaves).map(|(k, _)| k).filter(|k| field_name(k) == other).collect();
                bad.sort();
                bad.dedup();
                bad.join(", ")
            });
            assert!(unnamed.is_empty(), "{}: {unnamed}", lang.code());
        }
    }
}
