"""The core's messages in the user's words: it names what is wrong by its place in the document it was given
("parts[1].cuboids[0].max[2]"); FabGuide's objects say it with the labels the user gave them ("part 'Drawer' box
'Tray' top")."""
import re

PATH = re.compile(r"\b[a-z_]+\[\d+\](?:\.[a-z_]+(?:\[\d+\])?)*")
STEP = re.compile(r"([a-z_]+)(?:\[(\d+)\])?")
SIDES = {"min": ("left", "near", "bottom"), "max": ("right", "far", "top"),  # a field's [0..2], in words
         "drawn": ("width as drawn", "depth as drawn", "height as drawn"), "position": ("x", "y", "z"),
         "size": ("width", "depth", "height")}
WORKSLIKE = {"parts": "part", "cuboids": "box", "joints": "joint", "relationships": "relationship",
             "configurations": "configuration", "poses": "pose"}
FLATPACK = {"parts": "box", "constraints": "constraint", "inner_volumes": "inner volume", "boards": "master board"}
PACK = {"parts": "board", "boards": "master board"}


def in_words(message, document, nouns):
    """`message` with each field path into `document` (a dict as the core read it) said with the names of what
    it passes through, each list by its noun in `nouns`; a path that does not lead anywhere stays as it is."""
    return PATH.sub(lambda m: said(m.group(0), document, nouns), message)


def said(path, document, nouns):
    node, words = document, []
    for key, index in STEP.findall(path):
        items = node.get(key) if isinstance(node, dict) else None
        if index and key in SIDES and int(index) < 3:
            words.append(SIDES[key][int(index)])
        elif index and isinstance(items, list) and int(index) < len(items):
            node = items[int(index)]
            name = node if isinstance(node, str) else (node.get("name", node.get("id")) if isinstance(node, dict)
                                                       else None)
            if name is None:
                return path
            words.append("{} '{}'".format(nouns.get(key, key.replace("_", " ")), name))
        elif not index and isinstance(node, dict):
            words.append(key.replace("_", " "))
        else:
            return path
    return " ".join(words)
