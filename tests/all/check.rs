//! `phonglab check` on notebooks a student could have written: the exported worksheet
//! notebook with one catalogue mistake written into its cells, run by Python with NumPy
//! (as Jupyter runs it, its outputs saved in the notebook), then checked against the
//! assignment: the mistake is named, and the unchanged notebook is all right. A class
//! folder with hostile file names gives a report and marks that carry the names as data.
//! Skipped, saying so, where Python or NumPy is missing (CI installs Debian's python3-numpy).

use std::path::{Path, PathBuf};
use std::process::Command;

use glam::{DMat4, DVec3, DVec4};
use phonglab_core::Document;
use phonglab_core::camera::CameraSpec;
use phonglab_core::export::notebook::{Cell, cells, ipynb};
use phonglab_core::study::check::mistakes::CATALOGUE;

use crate::common;
use crate::common::TempDir;

/// Runs each notebook's code cells in order, in one namespace, with NumPy's default print
/// options, and saves it with its outputs at the path given after it; an exception stops
/// the run (as Run All does) and is saved as the cell's error output.
const RUNNER: &str = r#"
import io, json, sys, contextlib
args = sys.argv[1:]
for src, dst in zip(args[0::2], args[1::2]):
    nb = json.load(open(src, encoding="utf-8"))
    ns = {}
    stopped = False
    for cell in nb["cells"]:
        if cell["cell_type"] != "code" or stopped:
            continue
        out = io.StringIO()
        error = None
        with contextlib.redirect_stdout(out):
            try:
                exec("".join(cell["source"]), ns)
            except Exception as e:
                error = {"output_type": "error", "ename": type(e).__name__, "evalue": str(e), "traceback": []}
        cell["outputs"] = []
        if out.getvalue():
            cell["outputs"].append({"output_type": "stream", "name": "stdout", "text": out.getvalue().splitlines(True)})
        if error:
            cell["outputs"].append(error)
            stopped = True
    json.dump(nb, open(dst, "w", encoding="utf-8"))
"#;

fn python_with_numpy() -> Option<&'static str> {
    ["/usr/bin/python3", "python3"]
        .into_iter()
        .find(|p| Command::new(p).args(["-c", "import numpy"]).output().is_ok_and(|o| o.status.success()))
}

fn scene(name: &str) -> Document {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes").join(name);
    Document::from_toml_in(&std::fs::read_to_string(&path).unwrap(), path.parent()).unwrap()
}

/// The worksheet's scene (mview5, as `phonglab export` writes it).
fn worksheet() -> Document {
    scene("worksheet-mview5.toml")
}

/// The worksheet's scene under OpenGL's rules, the light below the surface: N.L < 0
/// while N.H > 0.
fn light_behind() -> Document {
    let mut d = worksheet();
    d.scene.rules = phonglab_core::Rules::OPENGL;
    d.scene.lights[0].position = DVec4::new(0.0, 0.0, -90.0, 1.0);
    d
}

/// A spotlight whose vertex lies 15 degrees off the axis, with cutoff `cutoff`.
fn spot(cutoff: f64) -> Document {
    let mut d = scene("spotlight.toml");
    d.scene.vertex.position = DVec4::new(0.8, 0.0, 0.0, 1.0);
    d.scene.lights[0].spot_cutoff = cutoff;
    d
}

/// `d` seen through a scale by `s` after its modelview.
fn scaled(mut d: Document, s: DVec3) -> Document {
    let m = DMat4::from_scale(s) * d.scene.eye_from_world;
    d.camera = CameraSpec::Matrix(m);
    d.scene.eye_from_world = m;
    d
}

/// The identity modelview: what the student computes is what they typed.
fn identity(mut d: Document) -> Document {
    d.camera = CameraSpec::Matrix(DMat4::IDENTITY);
    d.scene.eye_from_world = DMat4::IDENTITY;
    d.scene.world_from_object = DMat4::IDENTITY;
    d
}

/// The worksheet's vertex and light under OpenGL's rules, with a scene ambient and an
/// emission bright enough to take red past 1: every term of OpenGL's sum is printed.
fn opengl() -> Document {
    let mut d = worksheet();
    d.scene.rules = phonglab_core::Rules::OPENGL;
    d.scene.light_model.ambient = DVec4::new(0.2, 0.2, 0.2, 1.0);
    d.scene.material.emission = DVec4::new(1.0, 0.3, 0.1, 1.0);
    d
}

/// The worksheet with a directional light given an attenuation OpenGL ignores.
fn directional() -> Document {
    let mut d = worksheet();
    d.scene.lights[0].position = DVec4::new(0.0, 0.0, 1.0, 0.0);
    d.scene.lights[0].attenuation = [1.0, 0.0001, 0.00001];
    d
}

/// The worksheet's light fixed to the eye (placed under the identity, not `mview`).
fn eye_fixed() -> Document {
    let mut d = worksheet();
    d.scene.lights[0].placement = phonglab_core::scene::LightPlacement::Eye;
    d
}

/// The worksheet's rules with the light right below the vertex (L = -N): its specular
/// cosine N.H < 0.
fn worksheet_behind() -> Document {
    let mut d = worksheet();
    d.scene.lights[0].position = DVec4::new(-512.0, -384.0, -90.0, 1.0);
    d
}

/// The worksheet's light given as (0, 0, 180, 2): the same point, divided by its w.
fn light_w2() -> Document {
    let mut d = worksheet();
    d.scene.lights[0].position = DVec4::new(0.0, 0.0, 180.0, 2.0);
    d
}

/// The spotlight with an ambient colour: every term of its share is printed.
fn lit_spot() -> Document {
    let mut d = spot(25.0);
    d.scene.lights[0].ambient = DVec4::new(0.2, 0.2, 0.2, 1.0);
    d
}

/// A light above a surface turned away from the viewer: N.L > 0 while N.H < 0 (OpenGL's
/// rules, shininess 2 so the unclamped cosine's power is positive and printed).
fn turned_away() -> Document {
    let mut d = identity(worksheet());
    d.scene.rules = phonglab_core::Rules::OPENGL;
    d.scene.vertex.position = DVec4::new(0.0, 0.0, 0.0, 1.0);
    d.scene.vertex.normal = DVec3::new(0.0, 0.2, -0.98);
    d.scene.lights[0].position = DVec4::new(0.0, 1.0, 0.0, 0.0);
    d.scene.material.shininess = 2.0;
    d
}

/// A mistake's id, the assignment, and the edits (text found, its replacement).
type Case = (&'static str, Document, Vec<(&'static str, &'static str)>);

/// One catalogue mistake: its id, the assignment, and the edits that write it into the
/// exported notebook's cells.
fn cases() -> Vec<Case> {
    // OpenGL's rules under a non-uniform scale (x twice), where M n and (M^-1)^T n part.
    let mut opengl_scaled = worksheet();
    opengl_scaled.scene.rules = phonglab_core::Rules::OPENGL;
    opengl_scaled.scene.vertex.normal = DVec3::new(0.3, 0.5, 0.8);
    let opengl_scaled = scaled(opengl_scaled, DVec3::new(2.0, 1.0, 1.0));
    // The worksheet's M n, 1.6 long under a scale of z by 2.
    let stretched = scaled(worksheet(), DVec3::new(1.0, 1.0, 2.0));
    let mut w2 = worksheet();
    w2.scene.vertex.position = DVec4::new(-1024.0, -768.0, 0.0, 2.0);
    let mut acos = identity(worksheet());
    acos.scene.vertex.position = DVec4::new(0.0, 0.0, 0.0, 1.0);
    acos.scene.vertex.normal = DVec3::new(1.0, 2.0, 1.0);
    acos.scene.lights[0].position = DVec4::new(3.0, 6.0, 3.0, 1.0);
    vec![
        (
            "normal-by-modelview",
            opengl_scaled,
            vec![("np.matmul(normalMatrix, vertexNormal[:3])", "np.matmul(mview[:3, :3], vertexNormal[:3])")],
        ),
        (
            "normal-not-normalised",
            stretched.clone(),
            vec![("vertexNormal = vertexNormal/np.linalg.norm(vertexNormal)\n", "")],
        ),
        ("light-not-transformed", worksheet(), vec![("lightPos = np.matmul(mview, lightPos)\n", "")]),
        (
            "light-transformed-twice",
            worksheet(),
            vec![(
                "lightPos = np.matmul(mview, lightPos)\n",
                "lightPos = np.matmul(mview, np.matmul(mview, lightPos))\n",
            )],
        ),
        (
            "vectors-cell-run-twice",
            worksheet(),
            vec![
                (
                    "vertexNormal = np.matmul(mview, vertexNormal)\n",
                    "vertexNormal = np.matmul(mview, np.matmul(mview, vertexNormal))\n",
                ),
                (
                    "vertexPos = np.matmul(mview, vertexPos)\n",
                    "vertexPos = np.matmul(mview, np.matmul(mview, vertexPos))\n",
                ),
                (
                    "lightPos = np.matmul(mview, lightPos)\n",
                    "lightPos = np.matmul(mview, np.matmul(mview, lightPos))\n",
                ),
            ],
        ),
        ("vlv-reversed", worksheet(), vec![("vlv = (lightPos - vertexPos)", "vlv = (vertexPos - lightPos)")]),
        ("vlv-not-normalised", worksheet(), vec![("vlv = vlv/np.linalg.norm(vlv)\n", "")]),
        (
            "directional-as-point",
            directional(),
            vec![("if (lightPos[-1] == 0):", "if False:"), ("if lightPos[-1] == 0:", "if False:")],
        ),
        (
            "viewer-swapped",
            worksheet(),
            vec![
                ("#obs = np.array([0, 0, 0, 1])", "obs = np.array([0, 0, 0, 1])"),
                ("obs = vertexPos*np.array([1, 1, 0, 1])", "#obs = vertexPos*np.array([1, 1, 0, 1])"),
            ],
        ),
        ("halfway-not-normalised", worksheet(), vec![("H = H/np.linalg.norm(H)\n", "")]),
        ("specular-without-gate", light_behind(), vec![("if (cosTheta <= 0):", "if False:")]),
        ("diffuse-not-clamped", light_behind(), vec![("if (theta > m.pi*0.5):", "if False:")]),
        ("acos-past-one", acos, vec![("m.acos(min(max(cosTheta, -1), 1))", "m.acos(cosTheta)")]),
        ("spot-cutoff-radians", spot(25.0), vec![("m.cos(m.radians(spotCutoff))", "m.cos(spotCutoff)")]),
        (
            "spot-exponent-outside-cone",
            spot(6.3),
            vec![("    else:\n        spot = 0", "    else:\n        spot = max(cosSpot, 0)**spotCoef")],
        ),
        ("attenuation-multiplied", worksheet(), vec![("I = (Iamb + Idif + Ispec)/at", "I = (Iamb + Idif + Ispec)*at")]),
        (
            "attenuation-object-distance",
            stretched.clone(),
            vec![(
                "d = np.linalg.norm(lightPos - vertexPos);",
                "d = np.linalg.norm(np.array([0, 0, 90, 1]) - np.array([-512, -384, 0, 1]));",
            )],
        ),
        ("w-divide-forgotten", w2, vec![("vertexPos = vertexPos/vertexPos[3]\n", "")]),
        ("shininess-fraction", worksheet(), vec![("ns = 0.2*128;", "ns = 0.2;")]),
    ]
    .into_iter()
    .chain(more_cases())
    .collect()
}

/// The catalogue's later rounds: the mistakes students' notebooks were seen to make.
fn more_cases() -> Vec<Case> {
    [cases_2(), cases_3(), cases_4()].into_iter().flatten().collect()
}

/// The light's share, as the exported cells write it.
const ILIGHT: &str = "Ilight = spot*(Iamb + Idif + Ispec)/at";
/// The sum, as the exported cells write it.
const I: &str = "I = Iemi + Iscene + Ilight\n";

/// Catalogue mistakes, part 1 of the later rounds.
fn cases_2() -> Vec<Case> {
    vec![
        (
            "normal-matrix-with-translation",
            opengl(),
            vec![
                ("normalMatrix = np.linalg.inv(mview[:3, :3]).T", "normalMatrix = np.linalg.inv(mview).T"),
                (
                    "vertexNormal = np.append(np.matmul(normalMatrix, vertexNormal[:3]), 0)",
                    "vertexNormal = np.matmul(normalMatrix, vertexNormal)",
                ),
            ],
        ),
        ("normal-not-transformed", worksheet(), vec![("vertexNormal = np.matmul(mview, vertexNormal)\n", "")]),
        ("vertex-not-transformed", worksheet(), vec![("vertexPos = np.matmul(mview, vertexPos)\n", "")]),
        ("point-as-directional", worksheet(), vec![("if (lightPos[-1] == 0):", "if True:")]),
        ("viewer-reversed", worksheet(), vec![("vov = (obs - vertexPos)", "vov = (vertexPos - obs)")]),
        ("light-ambient-left-out", opengl(), vec![(ILIGHT, "Ilight = spot*(Idif + Ispec)/at")]),
        (
            "ambient-times-cosine",
            worksheet(),
            vec![("Iamb = Lamb*matAmb", "Iamb = Lamb*matAmb*np.dot(vertexNormal, vlv)")],
        ),
        ("colours-mixed-up", worksheet(), vec![("Idif = (Ldif*matDif)*cosTheta", "Idif = (Ldif*matSpec)*cosTheta")]),
        (
            "cos-theta-with-light-position",
            worksheet(),
            vec![("cosTheta = np.dot(vertexNormal, vlv);", "cosTheta = np.dot(vertexNormal, lightPos);")],
        ),
        (
            "theta-in-degrees",
            worksheet(),
            vec![(
                "theta = m.acos(min(max(cosTheta, -1), 1));",
                "theta = m.degrees(m.acos(min(max(cosTheta, -1), 1)));",
            )],
        ),
        (
            "reflection-for-halfway",
            worksheet(),
            vec![("cosBeta = np.dot(vertexNormal, H)", "cosBeta = np.dot(2*cosTheta*vertexNormal - vlv, vov)")],
        ),
        (
            "reflection-reversed",
            scene("phong-demo.toml"),
            vec![(
                "R = 2*max(np.dot(vertexNormal, vlv), 0)*vertexNormal - vlv",
                "R = vlv - 2*max(np.dot(vertexNormal, vlv), 0)*vertexNormal",
            )],
        ),
        (
            "specular-cosine-not-clamped",
            turned_away(),
            vec![("Ispec = (Lspec*matSpec)*(max(cosBeta, 0)**ns)", "Ispec = (Lspec*matSpec)*(cosBeta**ns)")],
        ),
        ("specular-left-out", opengl(), vec![(ILIGHT, "Ilight = spot*(Iamb + Idif)/at")]),
        ("attenuation-left-out", opengl(), vec![(ILIGHT, "Ilight = spot*(Iamb + Idif + Ispec)")]),
        ("ambient-not-attenuated", opengl(), vec![(ILIGHT, "Ilight = spot*(Iamb + (Idif + Ispec)/at)")]),
        (
            "attenuation-constant-left-out",
            worksheet(),
            vec![("at = atC + atLin*d + atQuad*d*d", "at = atLin*d + atQuad*d*d")],
        ),
        (
            "attenuation-quadratic-not-squared",
            worksheet(),
            vec![("at = atC + atLin*d + atQuad*d*d", "at = atC + atLin*d + atQuad*d")],
        ),
        (
            "distance-from-normalised-vlv",
            worksheet(),
            vec![("d = np.linalg.norm(lightPos - vertexPos);", "d = np.linalg.norm(vlv);")],
        ),
    ]
}

/// Catalogue mistakes, part 2 of the later rounds.
fn cases_3() -> Vec<Case> {
    vec![
        (
            "distance-squared",
            worksheet(),
            vec![("d = np.linalg.norm(lightPos - vertexPos);", "d = np.sum((lightPos - vertexPos)**2);")],
        ),
        ("spot-exponent-ignored", spot(25.0), vec![("spot = max(cosSpot, 0)**spotCoef", "spot = max(cosSpot, 0)")]),
        (
            "cone-test-inverted",
            spot(25.0),
            vec![("if cosSpot >= m.cos(m.radians(spotCutoff)):", "if cosSpot <= m.cos(m.radians(spotCutoff)):")],
        ),
        (
            "spot-angle-reversed",
            spot(25.0),
            vec![("cosSpot = np.dot(-vlv[:3], spotDir)", "cosSpot = np.dot(vlv[:3], spotDir)")],
        ),
        (
            "spot-direction-untransformed",
            spot(25.0),
            vec![("spotDir = np.matmul(mview[:3, :3], lightSpotDir[:3])", "spotDir = lightSpotDir[:3]")],
        ),
        ("spot-left-out", spot(25.0), vec![(ILIGHT, "Ilight = (Iamb + Idif + Ispec)/at")]),
        (
            "spot-on-whole-colour",
            spot(25.0),
            vec![(ILIGHT, "Ilight = (Iamb + Idif + Ispec)/at"), (I, "I = spot*(Iemi + Iscene + Ilight)\n")],
        ),
        (
            "light-left-out",
            scene("three-lights.toml"),
            vec![("I = Iemi + Iscene + sum(Ilight)", "I = Iemi + Iscene + Ilight[0] + Ilight[1] + Ilight[2]")],
        ),
        ("scene-ambient-left-out", opengl(), vec![(I, "I = Iemi + Ilight\n")]),
        ("scene-ambient-without-material", opengl(), vec![("Iscene = matAmb*sceneAmb", "Iscene = sceneAmb")]),
        ("emission-twice", opengl(), vec![(I, "I = Iemi + Iscene + Ilight + matEmi\n")]),
        (
            "colour-not-clamped",
            opengl(),
            vec![("glColor = np.append(np.clip((I)[:3], 0, 1), 1)", "glColor = np.append(I[:3], 1)")],
        ),
        (
            "normal-matrix-not-transposed",
            opengl(),
            vec![("normalMatrix = np.linalg.inv(mview[:3, :3]).T", "normalMatrix = np.linalg.inv(mview[:3, :3])")],
        ),
        (
            "row-vectors",
            worksheet(),
            vec![
                ("np.matmul(mview, vertexNormal)", "np.matmul(vertexNormal, mview)"),
                ("np.matmul(mview, vertexPos)", "np.matmul(vertexPos, mview)"),
                ("np.matmul(mview, lightPos)", "np.matmul(lightPos, mview)"),
            ],
        ),
        (
            "diffuse-angle-not-cosine",
            worksheet(),
            vec![("Idif = (Ldif*matDif)*cosTheta", "Idif = (Ldif*matDif)*theta")],
        ),
        ("halfway-with-view-reversed", worksheet(), vec![("H = (vlv + vov)", "H = (vlv - vov)")]),
        (
            "specular-angle-not-cosine",
            worksheet(),
            vec![("Ispec = (Lspec*matSpec)*(cosBeta**ns)", "Ispec = (Lspec*matSpec)*(beta**ns)")],
        ),
        (
            "attenuation-terms-swapped",
            worksheet(),
            vec![("at = atC + atLin*d + atQuad*d*d", "at = atC + atLin*d*d + atQuad*d")],
        ),
        (
            "spot-cutoff-not-cosine",
            spot(25.0),
            vec![("if cosSpot >= m.cos(m.radians(spotCutoff)):", "if cosSpot >= spotCutoff:")],
        ),
    ]
}

/// Catalogue mistakes, part 3 of the later rounds.
fn cases_4() -> Vec<Case> {
    vec![
        ("spot-on-diffuse-only", lit_spot(), vec![(ILIGHT, "Ilight = (Iamb + spot*Idif + Ispec)/at")]),
        (
            "only-last-light",
            scene("three-lights.toml"),
            vec![("I = Iemi + Iscene + sum(Ilight)", "I = Iemi + Iscene + Ilight[i]")],
        ),
        ("emission-left-out", opengl(), vec![(I, "I = Iscene + Ilight\n")]),
        (
            "colours-mixed-up",
            worksheet(),
            vec![
                ("Iamb = Lamb*matAmb", "Iamb = Lamb*matDif"),
                ("Idif = (Ldif*matDif)*cosTheta", "Idif = (Ldif*matAmb)*cosTheta"),
            ],
        ),
        (
            "normal-as-point",
            worksheet(),
            vec![("vertexNormal = np.array([0, 0, 1, 0])", "vertexNormal = np.array([0, 0, 1, 1])")],
        ),
        (
            "light-by-mview",
            eye_fixed(),
            vec![("lightPos = np.matmul(lightMview, lightPos)", "lightPos = np.matmul(mview, lightPos)")],
        ),
        (
            "spot-cutoff-halved",
            lit_spot(),
            vec![("if cosSpot >= m.cos(m.radians(spotCutoff)):", "if cosSpot >= m.cos(m.radians(spotCutoff/2)):")],
        ),
        ("spot-not-on-ambient", lit_spot(), vec![(ILIGHT, "Ilight = (Iamb + spot*(Idif + Ispec))/at")]),
        (
            "attenuation-on-whole-colour",
            opengl(),
            vec![(ILIGHT, "Ilight = spot*(Iamb + Idif + Ispec)"), (I, "I = (Iemi + Iscene + Ilight)/at\n")],
        ),
        (
            "attenuation-on-directional",
            directional(),
            vec![("if lightPos[-1] == 0:\n    at = 1", "if False:\n    at = 1")],
        ),
        ("vov-with-w", worksheet(), vec![("vov = (obs - vertexPos)", "vov = -vertexPos")]),
        (
            "specular-test-in-degrees",
            worksheet_behind(),
            vec![("if (beta > m.pi*0.5 or beta < 0):", "if (beta > 90 or beta < 0):")],
        ),
        (
            "specular-times-cosine",
            worksheet(),
            vec![("Ispec = (Lspec*matSpec)*(cosBeta**ns)", "Ispec = (Lspec*matSpec)*(cosBeta**ns)*cosTheta")],
        ),
        (
            "shininess-as-product",
            worksheet(),
            vec![("Ispec = (Lspec*matSpec)*(cosBeta**ns)", "Ispec = (Lspec*matSpec)*(cosBeta*ns)")],
        ),
        (
            "distance-without-w-divide",
            light_w2(),
            vec![(
                "d = np.linalg.norm(lightPos/lightPos[3] - vertexPos);",
                "d = np.linalg.norm(lightPos - vertexPos);",
            )],
        ),
        ("scene-ambient-wrong-material", opengl(), vec![("Iscene = matAmb*sceneAmb", "Iscene = matDif*sceneAmb")]),
        ("ambient-outside-share", lit_spot(), vec![(ILIGHT, "Ilight = Iamb + spot*(Idif + Ispec)/at")]),
        ("scene-ambient-times-light", lit_spot(), vec![("Iscene = matAmb*sceneAmb", "Iscene = matAmb*sceneAmb*Lamb")]),
        (
            "specular-of-diffuse-cosine",
            worksheet(),
            vec![("Ispec = (Lspec*matSpec)*(cosBeta**ns)", "Ispec = (Lspec*matSpec)*(cosTheta**ns)")],
        ),
        ("spot-exponent-as-factor", lit_spot(), vec![("spot = max(cosSpot, 0)**spotCoef", "spot = cosSpot*spotCoef")]),
        (
            "attenuation-inverted",
            worksheet(),
            vec![("at = atC + atLin*d + atQuad*d*d", "at = 1/(atC + atLin*d + atQuad*d*d)")],
        ),
        (
            "alpha-from-sum",
            opengl(),
            vec![(
                "glColor = np.append(np.clip((I)[:3], 0, 1), 1)",
                "glColor = np.append(np.clip((I)[:3], 0, 1), I[3])",
            )],
        ),
    ]
}

/// The exported notebook of `doc` with `edits` made in its code cells (each must be found).
fn edited(what: &str, doc: &Document, edits: &[(&str, &str)]) -> String {
    let mut cells = cells(doc, &phonglab_core::export::key(doc));
    for (old, new) in edits {
        let cell = cells.iter_mut().find_map(|c| match c {
            Cell::Code(text) if text.contains(old) => Some(text),
            _ => None,
        });
        let cell = cell.unwrap_or_else(|| panic!("{what}: the notebook has no {old}"));
        *cell = cell.replacen(old, new, 1);
    }
    ipynb(&cells)
}

/// Runs the notebooks in `dir` (`k.ipynb` into `k.ran.ipynb`).
fn run_all(python: &str, dir: &Path, count: usize) -> Vec<PathBuf> {
    let mut args = Vec::new();
    let mut out = Vec::new();
    for k in 0..count {
        args.push(dir.join(format!("{k}.ipynb")));
        args.push(dir.join(format!("{k}.ran.ipynb")));
        out.push(dir.join(format!("{k}.ran.ipynb")));
    }
    let run = Command::new(python).arg("-c").arg(RUNNER).args(&args).output().unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    out
}

fn check_json(work: &Path, scene: &Path) -> serde_json::Value {
    let out = common::phonglab(&["check", work.to_str().unwrap(), "--scene", scene.to_str().unwrap(), "--json"]);
    let json: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    // The exit code says the verdict, for scripts and autograders: 0 right, 1 wrong.
    let code = i32::from(json["verdict"] != "right");
    assert_eq!(out.status.code(), Some(code), "{json:#}");
    json
}

#[test]
fn every_catalogue_mistake_written_into_a_notebook_is_named_and_the_unchanged_one_is_right() {
    let Some(python) = python_with_numpy() else {
        eprintln!("SKIPPED: no python3 with NumPy here (Debian: python3-numpy)");
        return;
    };
    let dir = TempDir::new("check-mistakes");
    let cases = cases();
    // Every id of the catalogue has its notebook.
    for info in &CATALOGUE {
        assert!(cases.iter().any(|c| c.0 == info.id), "no notebook for {}", info.id);
    }
    let mut unchanged: Vec<Document> = vec![
        worksheet(),
        light_behind(),
        spot(25.0),
        spot(6.3),
        opengl(),
        turned_away(),
        lit_spot(),
        eye_fixed(),
        directional(),
        worksheet_behind(),
        light_w2(),
        scene("three-lights.toml"),
    ];
    unchanged.dedup_by(|a, b| a.to_toml().unwrap() == b.to_toml().unwrap());
    let n = cases.len();
    for (k, (id, doc, edits)) in cases.iter().enumerate() {
        std::fs::write(dir.path().join(format!("{k}.ipynb")), edited(id, doc, edits)).unwrap();
        std::fs::write(dir.path().join(format!("{k}.toml")), doc.to_toml().unwrap()).unwrap();
    }
    for (j, doc) in unchanged.iter().enumerate() {
        let k = n + j;
        std::fs::write(dir.path().join(format!("{k}.ipynb")), edited("unchanged", doc, &[])).unwrap();
        std::fs::write(dir.path().join(format!("{k}.toml")), doc.to_toml().unwrap()).unwrap();
    }
    let ran = run_all(python, dir.path(), n + unchanged.len());
    let mut failed = Vec::new();
    for (k, (id, ..)) in cases.iter().enumerate() {
        let json = check_json(&ran[k], &dir.path().join(format!("{k}.toml")));
        let ids: Vec<&str> = json["causes"].as_array().unwrap().iter().map(|c| c["id"].as_str().unwrap()).collect();
        // Where the printed values cannot tell mistakes apart (a spot of 0: outside the cone
        // for any of several reasons), each is named, the one whose formula the code holds
        // first; never the whole catalogue.
        if json["verdict"] != "wrong" || ids.first() != Some(id) || ids.len() > 6 {
            failed.push(format!("{id}: named {ids:?}: {json:#}"));
        }
    }
    assert!(failed.is_empty(), "{} of {n}:\n{}", failed.len(), failed.join("\n"));
    for j in 0..unchanged.len() {
        let k = n + j;
        let json = check_json(&ran[k], &dir.path().join(format!("{k}.toml")));
        assert_eq!(json["verdict"], "right", "unchanged {j}: {json:#}");
        assert!(json["first_wrong"].is_null() && json["causes"].as_array().unwrap().is_empty());
        assert!(json["steps"].as_array().unwrap().len() >= 12, "{json:#}");
    }
}

#[test]
fn a_notebook_saved_without_outputs_is_told_to_run_first() {
    let dir = TempDir::new("check-unrun");
    let path = dir.path().join("never-run.ipynb");
    std::fs::write(&path, edited("unchanged", &worksheet(), &[])).unwrap();
    let out = common::phonglab(&["check", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("Run it first"), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn a_class_with_hostile_names_gets_a_report_and_marks_that_keep_them_as_data() {
    let Some(python) = python_with_numpy() else {
        eprintln!("SKIPPED: no python3 with NumPy here (Debian: python3-numpy)");
        return;
    };
    let work = TempDir::new("check-work");
    let right = edited("right", &worksheet(), &[]);
    let wrong = edited("wrong", &worksheet(), &[("vlv = (lightPos - vertexPos)", "vlv = (vertexPos - lightPos)")]);
    std::fs::write(work.path().join("0.ipynb"), &right).unwrap();
    std::fs::write(work.path().join("1.ipynb"), &wrong).unwrap();
    let ran = run_all(python, work.path(), 2);
    let class = TempDir::new("check-class");
    let names = ["=HYPERLINK(\"http:x\")|ana.ipynb", "-2+3 [link](x) `b`.ipynb", "@SUM(A1) *c*.ipynb"];
    for (k, name) in names.iter().enumerate() {
        std::fs::copy(&ran[usize::from(k != 1)], class.path().join(name)).unwrap();
    }
    std::fs::write(class.path().join("not run.ipynb"), &right).unwrap();
    let out_dir = TempDir::new("check-out");
    let (report, csv) = (out_dir.path().join("report.md"), out_dir.path().join("marks.csv"));
    let out = common::phonglab_in(
        "pt_PT.UTF-8",
        &[
            "check",
            class.path().to_str().unwrap(),
            "--report",
            report.to_str().unwrap(),
            "--csv",
            csv.to_str().unwrap(),
        ],
    );
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let md = std::fs::read_to_string(&report).unwrap();
    assert!(md.contains("# Verificação da turma"), "{md}");
    // No --scene: said at the top, before the table.
    let note = md.find("Não foi indicada nenhuma --scene").expect("the no-scene note");
    assert!(note < md.find("| Aluno").unwrap(), "{md}");
    // The causes in the teacher's words, not their ids.
    assert!(md.contains("- vlv ao contrário: da luz para o vértice em vez do vértice para a luz: 2"), "{md}");
    assert!(!md.contains("vlv-reversed"), "{md}");
    // The unread notebook: a short verdict in its row, the reason in the list below.
    assert!(md.contains("| not run.ipynb | não lido |  |  |"), "{md}");
    assert!(!md.contains("- not run.ipynb: não lido"), "{md}");
    let unread = md.find("## Não lidos").expect("the list of notebooks not read");
    assert!(md[unread..].contains("- not run.ipynb: ") && md[unread..].contains("Execute-o primeiro"), "{md}");
    assert!(md.contains("\\[link\\](x) \\`b\\`"), "{md}");
    assert!(!md.contains("[link](x)"), "{md}");
    let marks = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = marks.lines().collect();
    assert_eq!(lines.len(), 5, "{marks}");
    for line in &lines[1..] {
        assert!(!line.starts_with(['=', '+', '-', '@']) && !line.starts_with("\"="), "{line}");
    }
    // A Portuguese spreadsheet's separator, the header and the verdict in the teacher's
    // words beside the causes, its id last for machines; after UTF-8's byte order mark
    // (Excel in Portuguese garbles "não" without it). The header was English.
    assert_eq!(lines[0], "\u{feff}ficheiro;veredicto;primeiro passo errado;causas;ids das causas;id do veredicto");
    assert!(
        marks.contains("\"'=HYPERLINK(\"\"http:x\"\")|ana.ipynb\";errado;vlv;vlv ao contrário: da luz para o vértice em vez do vértice para a luz;vlv-reversed;wrong\n"),
        "{marks}"
    );
    assert!(marks.contains("'-2+3 [link](x) `b`.ipynb;certo;;;;right\n"), "{marks}");
    assert!(marks.contains("not run.ipynb;não lido;"), "{marks}");
    assert!(lines[1..].iter().all(|l| l.ends_with(";wrong") || l.ends_with(";right") || l.ends_with(";unread")));
    let png = std::fs::read(out_dir.path().join("report.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG"));
    // A report asked to go over a submission is refused, and the submission is kept.
    let onto = class.path().join("@SUM(A1) *c*.ipynb");
    let before = std::fs::read(&onto).unwrap();
    let out = common::phonglab(&["check", class.path().to_str().unwrap(), "--csv", onto.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read(&onto).unwrap(), before);
}

/// A run that checked nothing is not right: text with no step of the worksheet in it
/// says so, and its JSON verdict is "incomplete" (issue 57; it was "wrong") with no first
/// wrong step and the reason.
#[test]
fn printed_text_with_no_step_is_not_right() {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_phonglab"))
        .args(["check", "--printed", "-", "--json"])
        .env_remove("LC_MESSAGES")
        .env_remove("LANG")
        .env("LC_ALL", "C.UTF-8")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(b"hello\n").unwrap();
    let out = child.wait_with_output().unwrap();
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["verdict"], "incomplete", "{json:#}");
    assert_eq!(out.status.code(), Some(1), "unchecked work is not right: exit 1");
    assert!(json["first_wrong"].is_null());
    assert_eq!(json["unchecked"]["id"], "nothing-compared");
    let dir = TempDir::new("check-hello");
    let path = dir.path().join("hello.txt");
    std::fs::write(&path, "hello\nModuleNotFoundError: No module named 'numpy'\n").unwrap();
    let out = common::phonglab(&["check", "--printed", path.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("ModuleNotFoundError: No module named 'numpy'"), "{text}");
    assert!(!text.contains("all right") && !text.contains("nothing printed that the key has"), "{text}");
    assert!(text.starts_with("scene: the worksheet's"), "{text}");
}

/// `--memory-budget` is honoured by check (it was ignored: `--memory-budget 1K` checked as
/// if not given): past it, the need and the budget that lets it run, nothing checked.
#[test]
fn check_honours_the_memory_budget() {
    let dir = TempDir::new("check-budget");
    let path = dir.path().join("printed.txt");
    std::fs::write(&path, "vlv =  [0.1 0.2 0.3 0.]\n").unwrap();
    let out =
        common::phonglab(&["--lang", "en", "check", "--printed", path.to_str().unwrap(), "--memory-budget", "1K"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("checking one submission of 24 bytes needs about"), "{err}");
    assert!(out.stdout.is_empty(), "nothing checked");
    let asked = err.split("needs --memory-budget ").nth(1).and_then(|r| r.split_whitespace().next()).expect("{err}");
    let out = common::phonglab(&["check", "--printed", path.to_str().unwrap(), "--memory-budget", asked]);
    assert_ne!(out.status.code(), Some(2), "{asked}: {}", String::from_utf8_lossy(&out.stderr));
    // A class folder: its notebooks counted, the largest named.
    let class = TempDir::new("check-budget-class");
    std::fs::write(class.path().join("a.ipynb"), "{}").unwrap();
    std::fs::write(class.path().join("b.ipynb"), "x".repeat(3000)).unwrap();
    let out = common::phonglab(&["--lang", "en", "check", class.path().to_str().unwrap(), "--memory-budget", "1K"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("checking 2 submissions, the largest 3 000 bytes (2.9 KiB), needs"), "{err}");
}

/// pt-PT speaks to the student in one register across check and diagnose (the formal,
/// as the rest of the app: "o seu", "a sua imagem"), and pt-BR with "você".
#[test]
fn check_and_diagnose_use_one_register() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (lang, informal) in [
        ("pt-PT", &["o teu", "a tua", "imprimiste", "escreveste", "Corre-o", "olha ", "imprime cada"][..]),
        ("pt-BR", &["o teu", "a tua", "imprimiste", "escreveste", "Corre-o"][..]),
    ] {
        for file in [root.join(format!("i18n/{lang}.ftl")), root.join(format!("crates/phonglab-core/i18n/{lang}.ftl"))]
        {
            let text = std::fs::read_to_string(&file).unwrap();
            for line in text.lines().filter(|l| l.starts_with("check-") || l.starts_with("diagnose-")) {
                for w in informal {
                    assert!(!line.contains(w), "{lang}: {w:?} in {line}");
                }
            }
        }
    }
}

#[test]
#[cfg(unix)] // symbolic links (Windows makes them only with a privilege)
fn a_link_in_a_class_folder_is_not_read_and_named_a_link() {
    let root = TempDir::new("check-links");
    let (class, secret) = (root.path().join("cls"), root.path().join("secret"));
    std::fs::create_dir_all(&class).unwrap();
    std::fs::create_dir_all(&secret).unwrap();
    let outside = secret.join("x.ipynb");
    std::fs::write(&outside, "{\n\"cells\": [],\napi_key = \"SECRET-42\"\n}\n").unwrap();
    std::os::unix::fs::symlink("../secret/x.ipynb", class.join("link.ipynb")).unwrap();
    std::os::unix::fs::symlink("/etc/passwd", class.join("passwd.ipynb")).unwrap();
    std::fs::write(class.join("own.ipynb"), edited("unchanged", &worksheet(), &[])).unwrap();
    let csv = root.path().join("marks.csv");
    let out = common::phonglab(&["check", class.to_str().unwrap(), "--csv", csv.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let marks = std::fs::read_to_string(&csv).unwrap();
    assert!(!marks.contains("SECRET-42") && !marks.contains("root:"), "{marks}");
    assert!(marks.contains("\nlink.ipynb,not read,,a link (a submission must be"), "{marks}");
    assert!(marks.contains("\npasswd.ipynb,not read,,a link (a submission must be"), "{marks}");
    assert!(marks.contains("\nown.ipynb,not read,") && !marks.contains("own.ipynb,not read,,a link"), "{marks}");
}

#[test]
#[cfg(unix)] // symbolic links (Windows makes them only with a privilege)
fn a_submission_that_is_a_link_is_refused_by_the_open_itself() {
    // The open refuses the link (O_NOFOLLOW), not a look before it: a link planted after
    // the class folder was listed is never followed.
    let root = TempDir::new("check-nofollow");
    let own = root.path().join("own.ipynb");
    std::fs::write(&own, edited("unchanged", &worksheet(), &[])).unwrap();
    let link = root.path().join("link.ipynb");
    std::os::unix::fs::symlink("own.ipynb", &link).unwrap();
    let refused = phonglab::platform::os::open_no_follow(&link).unwrap_err();
    assert!(phonglab::platform::os::is_link_refused(&refused), "{refused}");
    assert!(phonglab::platform::os::open_no_follow(&own).is_ok());
    let read = phonglab::io::student_code::read_notebook(&link).err().expect("a link read as a notebook");
    assert!(format!("{read:#}").contains("link.ipynb is a link: not read"), "{read:#}");
    // Each command that reads a submission: a notebook, printed text, a picture.
    std::fs::write(root.path().join("printed.txt"), "vlv =  [9. 9. 9. 0.]\n").unwrap();
    std::os::unix::fs::symlink("printed.txt", root.path().join("printed-link.txt")).unwrap();
    std::fs::write(root.path().join("p.png"), b"not read").unwrap();
    std::os::unix::fs::symlink("p.png", root.path().join("p-link.png")).unwrap();
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let (l, t, p) = (link.to_str().unwrap(), root.path().join("printed-link.txt"), root.path().join("p-link.png"));
    for args in [
        vec!["check", l],
        vec!["check", "--printed", t.to_str().unwrap()],
        vec!["diagnose", "--scene", scene.to_str().unwrap(), "--image", p.to_str().unwrap()],
    ] {
        let out = common::phonglab(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&out.stdout));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("is a link: not read"), "{args:?}: {err}");
    }
}

#[test]
#[cfg(unix)] // symbolic links (Windows makes them only with a privilege)
fn a_link_planted_at_the_charts_derived_name_is_refused_and_its_file_kept() {
    let root = TempDir::new("check-chartlink");
    let (class, sub, outside) = (root.path().join("cls"), root.path().join("sub"), root.path().join("outside"));
    for d in [&class, &sub, &outside] {
        std::fs::create_dir_all(d).unwrap();
    }
    std::fs::write(class.join("a.ipynb"), edited("unchanged", &worksheet(), &[])).unwrap();
    let notes = outside.join("notes.txt");
    std::fs::write(&notes, "my notes").unwrap();
    std::os::unix::fs::symlink("../outside/notes.txt", sub.join("turma.png")).unwrap();
    let report = sub.join("turma.md");
    let out = common::phonglab(&["check", class.to_str().unwrap(), "--report", report.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is a link"), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read_to_string(&notes).unwrap(), "my notes");
    assert!(!report.exists(), "nothing written");
}

#[test]
fn a_class_as_json_escapes_controls_in_file_names() {
    let class = TempDir::new("check-jsonnames");
    let names = ["a\u{9b}31m.ipynb", "b\u{202e}gnp.ipynb", "c\u{2028}d.ipynb"];
    for name in names {
        std::fs::write(class.path().join(name), edited("unchanged", &worksheet(), &[])).unwrap();
    }
    let out = common::phonglab(&["check", class.path().to_str().unwrap(), "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(!text.contains(['\u{9b}', '\u{202e}', '\u{2028}']), "{text:?}");
    assert!(text.contains("\\u202e"), "{text}");
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let files: Vec<&str> = json.as_array().unwrap().iter().map(|f| f["file"].as_str().unwrap()).collect();
    assert_eq!(files, names);
}

#[test]
fn a_step_printed_again_does_not_hide_the_earlier_wrong_one_and_junk_past_the_cap_is_refused() {
    let dir = TempDir::new("check-printed");
    let text = "vertexNormal =  [0.  0.6 0.8 0. ]\nvlv =  [9. 9. 9. 0.]\n\
                vlv =  [ 0.79220526  0.55887606 -0.2450885   0.        ]\n";
    let printed = dir.path().join("printed.txt");
    std::fs::write(&printed, text).unwrap();
    let out = common::phonglab(&["check", "--printed", printed.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(1), "wrong work exits 1: {}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["verdict"], "wrong", "{json:#}");
    assert_eq!(json["first_wrong"]["step"], "vlv", "{json:#}");
    assert_eq!(json["printed_twice"], serde_json::json!(["vlv"]), "{json:#}");
    let words = common::phonglab(&["check", "--printed", printed.to_str().unwrap()]);
    let words = String::from_utf8_lossy(&words.stdout);
    assert!(words.contains("printed more than once, with different values (each printing is checked): vlv"), "{words}");
    // 16384 junk numbers first: the work is refused whole, never checked in part.
    let mut junk: String = (0..4096).map(|k| format!("junk{k} = [1 1 1 1]\n")).collect();
    junk.push_str(text);
    std::fs::write(&printed, junk).unwrap();
    let out = common::phonglab(&["check", "--printed", printed.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stdout));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("prints more than 16384 numbers"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn the_class_report_names_each_students_steps_printed_twice_escaped_for_markdown() {
    let root = TempDir::new("check-twice");
    let class = root.path().join("cls");
    std::fs::create_dir_all(&class).unwrap();
    let printed = [
        "vertexNormal =  [0.  0.6 0.8 0. ]\n",
        "vlv =  [9. 9. 9. 0.]\n",
        "vlv =  [ 0.79220526  0.55887606 -0.2450885   0.        ]\n",
    ];
    let nb = serde_json::json!({"cells": [{
        "cell_type": "code",
        "source": ["import numpy as np\n", "vertexNormal = np.array([0, 0.6, 0.8, 0])\n"],
        "outputs": [{"output_type": "stream", "name": "stdout", "text": printed}],
    }]});
    // A name with Markdown's specials (Windows refuses `|` and `*` in a name: others there).
    let (name, shown) = if cfg!(windows) {
        ("ana_[twice]_.ipynb", r"ana\_\[twice\]\_.ipynb")
    } else {
        ("ana|*twice*.ipynb", r"ana\|\*twice\*.ipynb")
    };
    std::fs::write(class.join(name), nb.to_string()).unwrap();
    let report = root.path().join("turma.md");
    let out = common::phonglab(&["check", class.to_str().unwrap(), "--report", report.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "the report was written: {}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&report).unwrap();
    let section = "\n## Steps printed more than once with different values (each printing was checked)\n\n";
    let at = text.find(section).unwrap_or_else(|| panic!("no section:\n{text}"));
    let lines: Vec<&str> = text[at + section.len()..].lines().take_while(|l| !l.is_empty()).collect();
    assert_eq!(lines, [format!("- {shown}: vlv")], "{text}");
}

#[test]
fn a_given_that_is_not_finite_is_refused_by_check_naming_it() {
    let dir = TempDir::new("check-notfinite");
    let nb = serde_json::json!({"cells": [{
        "cell_type": "code",
        "source": ["import numpy as np\n", "vertexPos = np.array([1e999, -384, 0, 1])\n", "vertexNormal = np.array([0, 0, 1, 0])\n"],
        "outputs": [{"output_type": "stream", "name": "stdout", "text": ["vertexNormal =  [0. 0. 1. 0.]\n"]}],
    }]});
    let path = dir.path().join("inf.ipynb");
    std::fs::write(&path, nb.to_string()).unwrap();
    let out = common::phonglab(&["check", path.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{}{err}", String::from_utf8_lossy(&out.stdout));
    assert!(err.contains("not checked: a given is not a finite number (vertexPos (cell 1, line 2))"), "{err}");
}

#[test]
fn a_nan_given_written_with_numpy_is_refused_by_check_naming_it() {
    let dir = TempDir::new("check-nangiven");
    let nb = serde_json::json!({"cells": [{
        "cell_type": "code",
        "source": ["import numpy as np\n", "lightPos = np.array([0, 0, np.nan, 1])\n"],
        "outputs": [{"output_type": "stream", "name": "stdout", "text": ["lightPos =  [ 0.  0. nan  1.]\n"]}],
    }]});
    let path = dir.path().join("nan.ipynb");
    std::fs::write(&path, nb.to_string()).unwrap();
    let out = common::phonglab(&["check", path.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{}{err}", String::from_utf8_lossy(&out.stdout));
    assert!(err.contains("not checked: a given is not a finite number (lightPos (cell 1, line 2))"), "{err}");
}

#[test]
fn a_flag_that_does_not_apply_is_refused_and_one_submission_is_singular() {
    let dir = TempDir::new("check-flags");
    let nb = dir.path().join("a.ipynb");
    std::fs::write(&nb, edited("unchanged", &worksheet(), &[])).unwrap();
    let printed = dir.path().join("printed.txt");
    std::fs::write(&printed, "vlv =  [9. 9. 9. 0.]\n").unwrap();
    let report = dir.path().join("out").join("r.md");
    let (d, p, r) = (dir.path().to_str().unwrap(), printed.to_str().unwrap(), report.to_str().unwrap());
    let o = common::phonglab(&["check", d, "--printed", p]);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stdout));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("--printed checks one script"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    for flag in ["--report", "--csv"] {
        let o = common::phonglab(&["check", nb.to_str().unwrap(), flag, r]);
        assert_eq!(o.status.code(), Some(2), "{flag}: {}", String::from_utf8_lossy(&o.stdout));
        assert!(String::from_utf8_lossy(&o.stderr).contains("are a class's"), "{}", String::from_utf8_lossy(&o.stderr));
    }
    std::fs::create_dir_all(dir.path().join("out")).unwrap();
    std::fs::remove_file(&printed).unwrap();
    let o = common::phonglab(&["check", d, "--report", r]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The one notebook was saved without outputs: not read, and not counted as checked.
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("checked 0 submissions, one not read\n"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// The back side of two-sided lighting is checked too: its values, printed with `Back`
/// after their names, are compared; a mistake made only there makes the work wrong, with
/// its first wrong step on the back side.
#[test]
fn the_back_side_of_two_sided_lighting_is_checked() {
    let Some(python) = python_with_numpy() else {
        eprintln!("SKIPPED: no python3 with NumPy here (Debian: python3-numpy)");
        return;
    };
    let dir = TempDir::new("check-two-sided");
    let mut doc = light_behind();
    doc.scene.light_model.two_sided = true;
    doc.scene.light_model.ambient = DVec4::new(0.2, 0.2, 0.2, 1.0);
    doc.scene.material.emission = DVec4::new(0.1, 0.05, 0.0, 1.0);
    let back_only = [("IBack = IemiBack + IsceneBack + IlightBack", "IBack = IsceneBack + IlightBack")];
    for (k, edits) in [&[][..], &back_only[..]].into_iter().enumerate() {
        std::fs::write(dir.path().join(format!("{k}.ipynb")), edited("two-sided", &doc, edits)).unwrap();
        std::fs::write(dir.path().join(format!("{k}.toml")), doc.to_toml().unwrap()).unwrap();
    }
    let ran = run_all(python, dir.path(), 2);
    let right = check_json(&ran[0], &dir.path().join("0.toml"));
    assert_eq!(right["verdict"], "right", "{right:#}");
    let steps: Vec<&str> = right["steps"].as_array().unwrap().iter().map(|s| s["step"].as_str().unwrap()).collect();
    for back in ["cosThetaBack", "IdifBack", "IspecBack", "IBack", "glColorBack"] {
        assert!(steps.contains(&back), "{back} not compared: {steps:?}");
    }
    let out = common::phonglab(&[
        "check",
        ran[1].to_str().unwrap(),
        "--scene",
        dir.path().join("1.toml").to_str().unwrap(),
        "--json",
    ]);
    let wrong: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(wrong["verdict"], "wrong", "{wrong:#}");
    assert_eq!(wrong["first_wrong"]["step"], "IBack", "{wrong:#}");
}

/// A given changed in place is refused naming it (exit 2), never checked as a value
/// Python did not use; in a class folder a FIFO and a folder are named for what they are.
#[test]
fn a_given_changed_in_place_is_refused_and_a_fifo_or_folder_is_named() {
    let dir = TempDir::new("check-in-place");
    let nb = serde_json::json!({"cells": [{
        "cell_type": "code",
        "source": ["import numpy as np\n", "vertexPos = np.array([-512, -384, 0, 1])\n",
                   "lightPos = np.array([0, 0, 45, 1])\n", "lightPos[2] *= 2\n"],
        "outputs": [{"output_type": "stream", "name": "stdout", "text": ["vov =  [0. 0. 1. 0.]\n"]}],
    }]});
    let path = dir.path().join("a.ipynb");
    std::fs::write(&path, nb.to_string()).unwrap();
    let out = common::phonglab(&["check", path.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("a given is changed in place") && err.contains("lightPos (cell 1, line 4)"), "{err}");
    #[cfg(unix)]
    {
        let class = dir.path().join("class");
        std::fs::create_dir_all(class.join("dir.ipynb")).unwrap();
        let fifo = class.join("fifo.ipynb");
        assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
        let csv = dir.path().join("m.csv");
        let out = common::phonglab(&["check", class.to_str().unwrap(), "--csv", csv.to_str().unwrap()]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let marks = std::fs::read_to_string(&csv).unwrap();
        assert!(marks.contains("dir.ipynb,not read,,a folder"), "{marks}");
        assert!(marks.contains("fifo.ipynb,not read,,not a regular file"), "{marks}");
        assert!(!marks.contains("a link"), "{marks}");
    }
}

/// The exported worksheet notebook with H's mistake, run, and its outputs cleared from the
/// cell of H on (a hostile classmate's way to pass it): incomplete, never right, in the
/// terminal, the JSON, the report and the marks, the first step not printed named.
#[test]
fn a_notebook_cleared_from_its_first_wrong_step_on_is_incomplete_everywhere() {
    let Some(python) = python_with_numpy() else {
        eprintln!("SKIPPED: no python3 with NumPy here (Debian: python3-numpy)");
        return;
    };
    let dir = TempDir::new("check-cleared");
    let doc = worksheet();
    std::fs::write(dir.path().join("0.ipynb"), edited("H", &doc, &[("H = (vlv + vov)", "H = (vlv - vov)")])).unwrap();
    let ran = run_all(python, dir.path(), 1);
    let mut nb: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&ran[0]).unwrap()).unwrap();
    let mut cleared = false;
    for cell in nb["cells"].as_array_mut().unwrap() {
        let source: String = cell["source"].as_array().unwrap().iter().map(|l| l.as_str().unwrap()).collect();
        cleared |= source.contains("H = (vlv - vov)");
        if cleared {
            cell["outputs"] = serde_json::json!([]);
        }
    }
    assert!(cleared, "the notebook has H's cell");
    let class = dir.path().join("class");
    std::fs::create_dir_all(&class).unwrap();
    let work = class.join("cleared.ipynb");
    std::fs::write(&work, nb.to_string()).unwrap();
    let toml = dir.path().join("scene.toml");
    std::fs::write(&toml, doc.to_toml().unwrap()).unwrap();
    let json = check_json(&work, &toml);
    assert_eq!(json["verdict"], "incomplete", "{json:#}");
    assert_eq!(json["missing"], serde_json::json!(["Ispec", "I"]), "{json:#}");
    assert!(json["first_wrong"].is_null() && json["causes"].as_array().unwrap().is_empty(), "{json:#}");
    assert_eq!(json["unchecked"]["id"], "missing-steps", "{json:#}");
    let out = common::phonglab(&["check", work.to_str().unwrap(), "--scene", toml.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("incomplete: the worksheet asks for 2 steps this work does not print, the first Ispec: Ispec, I"),
        "{text}"
    );
    assert!(!text.contains("all right"), "{text}");
    let pt = common::phonglab_in("pt_PT.UTF-8", &["check", work.to_str().unwrap()]);
    let pt = String::from_utf8_lossy(&pt.stdout);
    assert!(pt.contains("incompleto: a ficha pede 2 passos que este trabalho não imprime, o primeiro Ispec"), "{pt}");
    // The class: the marks and the report say incomplete, and why.
    let (report, csv) = (dir.path().join("turma.md"), dir.path().join("notas.csv"));
    let out = common::phonglab(&[
        "check",
        class.to_str().unwrap(),
        "--scene",
        toml.to_str().unwrap(),
        "--report",
        report.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let marks = std::fs::read_to_string(&csv).unwrap();
    let row = marks.lines().nth(1).unwrap();
    assert!(row.starts_with("cleared.ipynb,incomplete,,") && row.contains("the first Ispec: Ispec, I"), "{marks}");
    let md = std::fs::read_to_string(&report).unwrap();
    assert!(md.contains("| cleared.ipynb | incomplete |  | incomplete: the worksheet asks for 2 steps"), "{md}");
    assert!(md.contains("- incomplete (a step not printed"), "{md}");
    // On the terminal, one line a student, the verdict said once.
    let out = common::phonglab(&["check", class.to_str().unwrap(), "--scene", toml.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.starts_with("cleared.ipynb: incomplete: the worksheet asks for 2 steps"), "{text}");
    assert!(!text.contains("incomplete: incomplete"), "{text}");
}

/// `check --printed -` given one right line is incomplete, every other step the worksheet
/// asks for named, and exits 1; the whole of what the worksheet prints is right.
#[test]
fn printed_text_of_one_right_line_is_incomplete() {
    use std::io::Write;
    let run = |text: &str| {
        let mut child = Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .args(["check", "--printed", "-", "--json"])
            .env_remove("LC_MESSAGES")
            .env_remove("LANG")
            .env("LC_ALL", "C.UTF-8")
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        child.stdin.take().unwrap().write_all(text.as_bytes()).unwrap();
        let out = child.wait_with_output().unwrap();
        (serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap(), out.status.code())
    };
    let vlv = "vlv =  [ 0.79220526  0.55887606 -0.2450885   0.        ]\n";
    let (json, code) = run(vlv);
    assert_eq!((json["verdict"].as_str(), code), (Some("incomplete"), Some(1)), "{json:#}");
    assert_eq!(json["missing"], serde_json::json!(["vertexNormal", "vov", "Iamb", "Idif", "Ispec", "I"]));
    assert_eq!(json["steps"][0]["verdict"], "right");
    // The worksheet's own printed output (its seven print lines) is whole and right.
    let sheet = "modelview = \n[[ 1.0e+00  0.0e+00  0.0e+00  0.0e+00]\n [ 0.0e+00  8.0e-01  6.0e-01  0.0e+00]\n \
                 [ 0.0e+00 -6.0e-01  8.0e-01 -9.6e+02]\n [ 0.0e+00  0.0e+00  0.0e+00  1.0e+00]]\n\
                 vertexNormal = [0.  0.6 0.8 0. ]\nvlv = [ 0.79220526  0.55887606 -0.2450885   0.      ]\n\
                 vov = [0. 0. 1. 0.]\nIamb = [0.2125 0.1275 0.054 0.      ]\n\
                 Idif = [0.09942795 0.05965677 0.0252664 0.]\nIspec = [0.00040551 0.00028017 0.00017179 0.]\n\
                 I = [0.05958709 0.03575929 0.01515525 0.          ]\n";
    let (json, code) = run(sheet);
    assert_eq!((json["verdict"].as_str(), code), (Some("right"), Some(0)), "{json:#}");
    assert_eq!(json["missing"], serde_json::json!([]));
}

/// Issue 57: work printed with too few digits to tell the key from a mistake's value (the
/// specular left out, printed under `np.set_printoptions(precision=2)`) is not right in
/// JSON either: the verdict `incomplete`, why `too-few-digits`, the step's verdict
/// `too-few-digits`; the exit status not 0.
#[test]
fn too_few_digits_are_incomplete_in_json() {
    let dir = TempDir::new("check-digits");
    let text = "vertexNormal =  [0.  0.6 0.8 0. ]\nvlv =  [ 0.79  0.56 -0.25  0.  ]\nvov =  [0. 0. 1. 0.]\n\
                Iamb =  [0.21 0.13 0.05 0.  ]\nIdif =  [0.1  0.06 0.03 0.  ]\nIspec =  [0. 0. 0. 0.]\n\
                I =  [0.06 0.04 0.02 0.  ]\n";
    let printed = dir.path().join("p2.txt");
    std::fs::write(&printed, text).unwrap();
    let out = common::phonglab(&["check", "--printed", printed.to_str().unwrap(), "--json"]);
    assert_ne!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["verdict"], "incomplete", "{json:#}");
    assert_eq!(json["unchecked"]["id"], "too-few-digits", "{json:#}");
    let ispec = json["steps"].as_array().unwrap().iter().find(|s| s["step"] == "Ispec").unwrap();
    assert_eq!(ispec["verdict"], "too-few-digits", "{json:#}");
    assert!(ispec["words"].as_str().unwrap().contains("np.set_printoptions(precision=8)"), "{json:#}");
}

#[test]
fn a_class_is_checked_smallest_first_so_huge_files_named_first_cannot_starve_the_rest() {
    // A hostile's huge notebook named first used the whole time cap, and every honest
    // classmate after it was "not read". With no time at all, only the first file checked
    // is read: the smallest; the report still lists the files in name order.
    let class = TempDir::new("check-smallest-first");
    let nb = |padding: usize| {
        serde_json::json!({"cells": [
            {"cell_type": "markdown", "source": ["x".repeat(padding)]},
            {"cell_type": "code",
             "source": ["import numpy as np\n", "vertexNormal = np.array([0, 0.6, 0.8, 0])\n"],
             "outputs": [{"output_type": "stream", "name": "stdout", "text": ["vertexNormal =  [0.  0.6 0.8 0. ]\n"]}]},
        ]})
        .to_string()
    };
    std::fs::write(class.path().join("a-huge.ipynb"), nb(200_000)).unwrap();
    std::fs::write(class.path().join("b-honest.ipynb"), nb(0)).unwrap();
    let marked = phonglab::cli::check_class::mark_all(class.path(), None, std::time::Duration::ZERO).unwrap();
    let names: Vec<&str> = marked.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names, ["a-huge.ipynb", "b-honest.ipynb"]);
    let why = marked[0].check.as_ref().err().cloned().unwrap_or_default();
    assert!(why.starts_with("not read: the class's check took its 0 s"), "{why}");
    assert!(marked[1].check.is_ok(), "{:?}", marked[1].check.as_ref().err());
}

/// A classmate who can write to a shared class folder drops 1003 junk notebooks, three of
/// them FIFOs: the class is still marked (the honest notebook right, the FIFOs named), where
/// a cap of 1000 refused the whole folder with "…: > 1000 .ipynb" and no marks (hostile,
/// round 4).
#[cfg(unix)]
#[test]
fn a_folder_flooded_with_junk_and_fifos_still_marks_the_class() {
    let class = TempDir::new("check-flood");
    for k in 0..1000 {
        std::fs::write(class.path().join(format!("junk-{k:04}.ipynb")), "{}").unwrap();
    }
    for k in 0..3 {
        let fifo = std::ffi::CString::new(class.path().join(format!("fifo-{k}.ipynb")).to_str().unwrap()).unwrap();
        // SAFETY: a path this test made, NUL-terminated.
        assert_eq!(unsafe { libc::mkfifo(fifo.as_ptr(), 0o600) }, 0);
    }
    let text = phonglab_core::export::notebook::ipynb(&[]);
    std::fs::write(class.path().join("zz-honest.ipynb"), text).unwrap();
    let marked = phonglab::cli::check_class::mark_all(class.path(), None, std::time::Duration::from_secs(120)).unwrap();
    assert_eq!(marked.len(), 1004);
    let fifo = marked.iter().find(|m| m.name == "fifo-0.ipynb").expect("named");
    assert!(fifo.check.as_ref().err().is_some_and(|e| e.contains("not a regular file")), "{:?}", fifo.check);
    let honest = marked.iter().find(|m| m.name == "zz-honest.ipynb").expect("named");
    let why = honest.check.as_ref().err().cloned().unwrap_or_default();
    assert!(!why.contains("not read"), "read: {why}");
}
