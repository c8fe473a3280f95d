"""What the docs scripts share: a generated block put between its markers in a page."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]


def replace_block(page, name, text):
    """Puts `text` between the page's  <!-- NAME: begin -->  and  <!-- NAME: end -->  markers."""
    path = ROOT / page
    old = path.read_text()
    pattern = re.compile(r"(<!-- %s: begin -->\n).*?(<!-- %s: end -->)" % (name, name), re.S)
    if not pattern.search(old):
        sys.exit(f"{page}: no {name} markers")
    path.write_text(pattern.sub(lambda m: m.group(1) + text + m.group(2), old))
