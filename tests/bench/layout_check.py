"""Independent check of a layout JSON against its input (the layout contract of docs/formats.md):
every unit of demand placed once, sizes match the part (turned by its rotation), nothing leaves its
board, no two parts overlap. Returns a list of problems, empty when the layout is valid."""
import itertools


def demand_of_strip_instance(instance):
    """{part index: (width, height, demand)} of an OR-Datasets instance."""
    return {i: (item["Length"], item["Height"], item.get("Demand", 1)) for i, item in enumerate(instance["Items"])}


def demand_of_pack_problem(problem):
    """{part id: (width, height, quantity)} of a *.pack.json problem."""
    return {p["id"]: (p["width"], p["height"], p.get("quantity", 1)) for p in problem["parts"]}


def problems(layout, demand, board_sizes, clearance=0.0, eps=1e-6):
    """board_sizes(i) -> (width, height, trim) of layout board i; clearance = kerf + spacing."""
    found = []
    placed = {}
    for n, p in enumerate(layout["placements"]):
        part = p["part"]
        if part not in demand:
            found.append("placement {}: unknown part {!r}".format(n, part))
            continue
        placed[part] = placed.get(part, 0) + 1
        w, h, _ = demand[part]
        size = (w, h) if p["rotation"] % 180 == 0 else (h, w)
        if abs(p["width"] - size[0]) > eps or abs(p["height"] - size[1]) > eps:
            found.append("placement {}: size {}x{} is not part {!r} turned {}".format(
                n, p["width"], p["height"], part, p["rotation"]))
        bw, bh, trim = board_sizes(p["board"])
        if p["x"] < trim - eps or p["y"] < trim - eps or p["x"] + p["width"] > bw - trim + eps or \
                p["y"] + p["height"] > bh - trim + eps:
            found.append("placement {}: part {!r} leaves board {}".format(n, part, p["board"]))
    for part, (_, _, quantity) in demand.items():
        if placed.get(part, 0) != quantity:
            found.append("part {!r}: placed {} times, demand {}".format(part, placed.get(part, 0), quantity))
    on_board = {}
    for n, p in enumerate(layout["placements"]):
        on_board.setdefault(p["board"], []).append((n, p))
    for placed_on in on_board.values():
        for (i, a), (j, b) in itertools.combinations(placed_on, 2):
            apart_x = a["x"] + a["width"] + clearance <= b["x"] + eps or b["x"] + b["width"] + clearance <= a["x"] + eps
            apart_y = (a["y"] + a["height"] + clearance <= b["y"] + eps or
                       b["y"] + b["height"] + clearance <= a["y"] + eps)
            if not (apart_x or apart_y):
                found.append("placements {} and {} overlap (or are closer than {})".format(i, j, clearance))
    return found
