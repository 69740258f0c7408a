"""LMGC90's example cases (../shared/lmgc90-examples, or $LMGC_SHARED_DIR) for the scripts that run
them: the rigid examples by name, and a scratch copy of a case with its command.py edited."""
import os
import shutil

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.environ.get("LMGC_SHARED_DIR", os.path.join(os.path.dirname(ROOT), "shared"))
EXAMPLES = os.path.join(SHARED, "lmgc90-examples")


def rigid_examples(only=None):
    """RIGID_2D/<name> and RIGID_3D/<name> of every example holding a DATBOX/ (names containing `only`)."""
    out = []
    for dimension in ("RIGID_2D", "RIGID_3D"):
        folder = os.path.join(EXAMPLES, dimension)
        for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
            if only and only not in name:
                continue
            if os.path.isdir(os.path.join(folder, name, "DATBOX")):
                out.append(os.path.join(dimension, name))
    return out


def prepare_case(source, work, edit=None):
    """`work` made afresh with source's DATBOX/ and command.py, the script passed through `edit`."""
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)
    shutil.copytree(os.path.join(source, "DATBOX"), os.path.join(work, "DATBOX"))
    script = os.path.join(source, "command.py")
    if os.path.exists(script):
        with open(script) as f:
            text = f.read()
        with open(os.path.join(work, "command.py"), "w") as f:
            f.write(edit(text) if edit else text)
