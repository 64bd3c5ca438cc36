"""Files in and out: the command line's own readers and writer (a regular file under its cap,
never waiting on a FIFO; written whole, through a link, never over a device or the mesh)."""

import os
import stat
import threading

import pytest

import phonglab

GOOD = 'rules = "worksheet"\n[material]\nshininess = 20\n'


def finishes(function, seconds=20):
    """Runs `function` on a thread and returns what it raised (None if nothing), failing
    the test when it has not finished in `seconds` (a read that blocks on a FIFO)."""
    raised = []

    def run():
        try:
            function()
            raised.append(None)
        except BaseException as e:  # noqa: BLE001 - handed back to the test
            raised.append(e)

    t = threading.Thread(target=run, daemon=True)
    t.start()
    t.join(seconds)
    assert raised, "still reading: it waits on the FIFO"
    return raised[0]


@pytest.mark.parametrize("name, reader", [("f.toml", phonglab.Scene.load), ("f.ipynb", phonglab.Scene.from_notebook)])
def test_a_fifo_is_refused_at_once(tmp_path, name, reader):
    fifo = tmp_path / name
    os.mkfifo(fifo)
    e = finishes(lambda: reader(fifo))
    assert isinstance(e, phonglab.SceneError), e
    assert "is not a regular file" in str(e) and name in str(e)


def test_devices_links_to_devices_and_folders_are_refused(tmp_path):
    link = tmp_path / "z.toml"
    link.symlink_to("/dev/zero")
    for path in [link, "/dev/zero", tmp_path]:
        with pytest.raises(phonglab.SceneError, match="is not a regular file"):
            phonglab.Scene.load(path)


def test_a_file_over_the_cap_is_refused_before_it_is_read(tmp_path):
    big = tmp_path / "big.toml"
    with open(big, "wb") as f:
        f.truncate(3 << 30)  # sparse: 3 GiB that take no disk
    with pytest.raises(phonglab.SceneError, match=r"big.toml is 3.221.225.472 bytes \(3072.0 MiB\); phonglab reads scene files of at most 1.048.576 bytes"):
        phonglab.Scene.load(big)
    nb = tmp_path / "big.ipynb"
    with open(nb, "wb") as f:
        f.truncate((16 << 20) + 1)
    with pytest.raises(phonglab.SceneError, match="notebooks and scripts of at most 16"):
        phonglab.Scene.from_notebook(nb)


def test_from_toml_has_the_scene_files_cap():
    with pytest.raises(phonglab.SceneError, match=r"Scene.from_toml\(text\) is 1.0\d\d.\d\d\d bytes \(1.0 MiB\); phonglab reads scene files of at most"):
        phonglab.Scene.from_toml(f'name = "{"x" * (1 << 20)}"\n' + GOOD)


def test_a_file_that_is_not_utf8_is_a_scene_error(tmp_path):
    bad = tmp_path / "latin.toml"
    bad.write_bytes(b'name = "caf\xe9"\n' + GOOD.encode())
    with pytest.raises(phonglab.SceneError, match=r"latin.toml is not UTF-8 text \(byte 11\)"):
        phonglab.Scene.load(bad)


def test_missing_files_and_folders_are_scene_errors_naming_them(tmp_path):
    with pytest.raises(phonglab.SceneError, match="cannot read worksheet.toml: it does not exist"):
        phonglab.Scene.load("worksheet.toml")
    with pytest.raises(phonglab.SceneError, match="is not a regular file"):
        phonglab.Scene.load(tmp_path)
    with pytest.raises(phonglab.SceneError, match=r"cannot write .*nowhere/x.toml: create: its folder .*nowhere does not exist"):
        phonglab.Scene.worksheet(5).save(tmp_path / "nowhere" / "x.toml")
    assert os.listdir(tmp_path) == []


def test_control_characters_in_a_path_and_in_a_files_lines_are_written_visibly(tmp_path):
    name = tmp_path / "a\x1b[31mred\x07.toml"
    with pytest.raises(phonglab.SceneError) as raised:
        phonglab.Scene.load(name)
    text = str(raised.value)
    assert "\x1b" not in text and "\x07" not in text
    assert "a\\u{1B}[31mred\\u{7}.toml" in text, text
    bad = tmp_path / "keys.toml"
    bad.write_text(GOOD + "[view]\nob\x1b[2Jject\u202e = 1\n")
    with pytest.raises(phonglab.SceneError) as raised:
        phonglab.Scene.load(bad)
    text = str(raised.value)
    assert "\x1b" not in text and "\u202e" not in text, text
    assert "\\u{1B}" in text and "\\u{202E}" in text, text


def test_save_through_a_link_replaces_the_file_it_names_and_the_link_stays(tmp_path):
    target = tmp_path / "target.toml"
    target.write_text("old")
    link = tmp_path / "link.toml"
    link.symlink_to("target.toml")
    phonglab.Scene.worksheet(3).save(link)
    assert link.is_symlink() and os.readlink(link) == "target.toml"
    assert phonglab.Scene.load(target).to_toml() == phonglab.Scene.worksheet(3).to_toml()
    dangling = tmp_path / "dangling.toml"
    dangling.symlink_to("made.toml")
    phonglab.Scene.worksheet(2).save(dangling)
    assert dangling.is_symlink() and (tmp_path / "made.toml").is_file()


def test_save_onto_a_fifo_or_a_device_is_refused_and_leaves_it(tmp_path):
    fifo = tmp_path / "f.toml"
    os.mkfifo(fifo)
    e = finishes(lambda: phonglab.Scene.worksheet(5).save(fifo))
    assert isinstance(e, phonglab.SceneError) and "not a regular file" in str(e) and "nothing was written" in str(e), e
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    with pytest.raises(phonglab.SceneError, match="not a regular file"):
        phonglab.Scene.worksheet(5).save("/dev/null")
    assert stat.S_ISCHR(os.lstat("/dev/null").st_mode)


def test_save_keeps_a_files_permissions_and_gives_a_new_one_the_usual_ones(tmp_path):
    old = os.umask(0o022)
    try:
        new = tmp_path / "new.toml"
        phonglab.Scene.worksheet(5).save(new)
        assert stat.S_IMODE(os.stat(new).st_mode) == 0o644
        os.chmod(new, 0o600)
        phonglab.Scene.worksheet(3).save(new)
        assert stat.S_IMODE(os.stat(new).st_mode) == 0o600
        assert phonglab.Scene.load(new).to_toml() == phonglab.Scene.worksheet(3).to_toml()
    finally:
        os.umask(old)


def test_save_refuses_the_scenes_own_mesh(tmp_path):
    folder = tmp_path / "m1"
    folder.mkdir()
    mesh = folder / "mesh.obj"
    mesh.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    (folder / "s.toml").write_text(GOOD + '[view]\nobject = "obj"\nobj = "mesh.obj"\n')
    scene = phonglab.Scene.load(folder / "s.toml")
    with pytest.raises(phonglab.SceneError, match="is the mesh"):
        scene.save(mesh)
    assert mesh.read_text().startswith("v 0 0 0")
    scene.save(folder / "s.toml")  # its own scene file: Save, as the app's


def test_a_notebooks_name_with_control_characters_is_written_visibly_and_saves_and_loads(tmp_path, cli):
    path = tmp_path / "w\x1b[1m.ipynb"
    cli("export", "--to", "notebook", "-o", path)
    scene = phonglab.Scene.from_notebook(path)
    assert "\x1b" not in scene.name and "\\u{1B}" in scene.name, scene.name
    scene.save(tmp_path / "w.toml")
    assert phonglab.Scene.load(tmp_path / "w.toml").name == scene.name


@pytest.mark.parametrize("lang, words", [("en", "it is not on PyPI yet"), ("pt-PT", "ainda não está no PyPI"), ("pt-BR", "ainda não está no PyPI")])
def test_the_exported_notebook_says_how_to_install_the_package_until_it_is_on_pypi(tmp_path, cli, lang, words):
    import json

    path = tmp_path / "w.ipynb"
    cli("export", "--to", "notebook", "--lang", lang, "-o", path)
    cells = json.loads(path.read_text())["cells"]
    text = "".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")
    assert words in text and "`pip install phonglab-*.whl`" in text, text[-600:]


def test_save_refuses_the_notebook_the_scene_was_imported_from(tmp_path, cli):
    path = tmp_path / "hw.ipynb"
    cli("export", "--to", "notebook", "-o", path)
    before = path.read_bytes()
    scene = phonglab.Scene.from_notebook(path)
    with pytest.raises(phonglab.SceneError, match="is the notebook or script .*hw.ipynb, which this command reads"):
        scene.save(path)
    assert path.read_bytes() == before
    scene.save(tmp_path / "hw.toml")


def test_a_share_link_loads_as_the_scene_it_carries():
    # N1: a link is taken wherever a scene file is, decoded as the command line decodes it.
    s = phonglab.Scene.worksheet(5)
    s.material.shininess = 77.0
    link = phonglab.share_link(s)
    read = phonglab.Scene.load(link)
    assert read.material.shininess == 77.0
    assert read.to_toml() == s.to_toml()
    assert phonglab.light(read).I.tolist() == phonglab.light(s).I.tolist()


@pytest.mark.parametrize(
    "lang, damaged",
    [
        ("en", "the link is damaged: it was cut or changed"),
        ("pt-PT", "a ligação está danificada: foi cortada ou alterada"),
        ("pt-BR", "o link está danificado: foi cortado ou alterado"),
    ],
)
def test_a_damaged_link_is_said_in_words_not_the_decoders(lang, damaged):
    # N1, N2: a cut or garbled link says it is damaged, never "it does not exist", and
    # carries no decoder text.
    link = phonglab.share_link(phonglab.Scene.worksheet(5))
    try:
        phonglab.set_language(lang)
        for bad in [link[:200], "https://phonglab.github.io/phonglab/#v1.garbage"]:
            with pytest.raises(phonglab.SceneError) as e:
                phonglab.Scene.load(bad)
            said = str(e.value)
            assert damaged in said, said
            for jargon in ["does not exist", "Invalid", "offset", "Failed", "Progress", "("]:
                assert jargon not in said, said
    finally:
        phonglab.set_language("en")


def test_english_left_in_portuguese_messages_is_gone(tmp_path):
    # N4: a notebook given to Scene.load; a text where a number is; an infinity.
    notebook = tmp_path / "hw.ipynb"
    notebook.write_text('{"cells": []}')
    bad = tmp_path / "bad.toml"
    bad.write_text('[material]\nshininess = "abc"\n')
    try:
        phonglab.set_language("pt-PT")
        with pytest.raises(phonglab.SceneError) as e:
            phonglab.Scene.load(notebook)
        said = str(e.value)
        assert "é um caderno ou um script, não um ficheiro de cena" in said and "Scene.from_notebook" in said, said
        assert "invalid" not in said and "expected" not in said, said
        with pytest.raises(phonglab.SceneError) as e:
            phonglab.Scene.load(bad)
        said = str(e.value)
        assert 'tipo inválido: o texto "abc", esperava-se um número' in said, said
        assert "f64" not in said and "string" not in said, said
    finally:
        phonglab.set_language("en")
    lit = phonglab.light(phonglab.Scene.worksheet(5), vertex=[1, 2, 3, 0], lang="pt-BR")
    for shown in (lit.explain(), lit._repr_html_(), lit._repr_markdown_()):
        assert "Infinity" not in shown
    assert "d = inf" in lit.explain(), lit.explain()
