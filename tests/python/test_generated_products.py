"""Generated products with known answers (tests/gen): products valid by construction, drawn roughly,
a third made contradictory with the conflict known, solved by `fabguide solve` and judged by the independent
checker; a sample printed and judged by the print checker. Every seed that ever failed is kept in
tests/gen/regressions.json and runs here too. `make fuzz-products` runs thousands."""
import json
import os
import random
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
GEN = os.path.join(HERE, "..", "gen")
sys.path.insert(0, GEN)
import contradict  # noqa: E402
import fuzz_products  # noqa: E402
import products  # noqa: E402
import roughen  # noqa: E402
import workslike_checker  # noqa: E402
from conftest import sample  # noqa: E402

SOLVED = sample(range(240))  # solve + check: a few hundred in CI
PRINTED = sample(range(0, 200, 10))  # fitted prints of every tenth


def regressions():
    """The rough models that once failed (tests/gen/regressions), each with what it is known to be."""
    folder = os.path.join(GEN, "regressions")
    return sample(sorted(f for f in os.listdir(folder) if f.endswith(".workslike.json")))


def known(what, seeds):
    """The seeds, those with a failure known and not fixed yet (tests/gen/known_failures.json) marked as
    expected to fail: strictly, so that fixing one says to take it off the list."""
    with open(os.path.join(GEN, "known_failures.json")) as f:
        failures = {k["seed"]: k for k in json.load(f) if k["what"] == what}
    return [pytest.param(s, marks=pytest.mark.xfail(strict=True, reason=failures[s]["class"])) if s in failures
            else s for s in seeds]


@pytest.mark.parametrize("seed", known("solve", SOLVED))
def test_generated_product_solves_and_checks(fabguide_cli, seed):
    seed_, kind, detail, *_ = fuzz_products.judge(seed, cli=fabguide_cli)
    assert kind is None, "seed %d: %s\n%s\n(rerun: python3 tests/gen/fuzz_products.py --seeds %d --keep DIR)" % (
        seed, kind, detail, seed)


@pytest.mark.parametrize("seed", known("print", PRINTED))
def test_generated_product_prints_and_checks(fabguide_cli, seed):
    if fuzz_products.case(seed)["known"]:
        pytest.skip("contradictory: nothing to print")
    seed_, kind, detail, *_ = fuzz_products.judge(seed, cli=fabguide_cli, print_it=True)
    assert kind is None, "seed %d: %s\n%s" % (seed, kind, detail)


@pytest.mark.parametrize("name", regressions())
def test_a_product_that_once_failed(fabguide_cli, name):
    with open(os.path.join(GEN, "regressions", name)) as f:
        model = json.load(f)
    generated = model.pop("generated")
    verdict = fuzz_products.judge_model(model, generated["known"], fabguide_cli, print_it=bool(generated.get("print")))
    assert verdict is None, "%s (once: %s): %s" % (name, generated["failure"][0], verdict)


def test_generated_products_are_valid_by_construction_and_varied():
    """The clean designs pass the checker with no warning; together they show every feature of the grammar."""
    features = set()
    for seed in range(60):
        p = products.generate(seed)
        problems, warnings = workslike_checker.check_all(p.model, p.model)
        assert problems == [] and warnings == [], (seed, problems, warnings)
        features |= p.features
    for feature in ("door", "flap down", "flap up", "drawer", "pull-out", "chain", "bin", "pocket door",
                    "sliding door", "knob", "pull", "lid", "folding lid", "legs", "link", "links doubled", "cover",
                    "fit_inside", "support", "flush", "geometric", "just cover", "locked carcass"):
        assert feature in features, feature
    assert any(f.startswith("door at ") for f in features)  # turns that are not quarter turns
    assert {"2 configurations", "3 configurations", "4 configurations"} <= features


def test_rough_drawings_need_the_solve():
    """The rough pass spoils the designs: most of them fail the checker as drawn (else the suite proves
    little); the contradictory ones fail it where their conflict is."""
    spoiled = 0
    for seed in range(60):
        model = products.generate(seed).model
        rough, _ = roughen.roughen(model, random.Random(seed))
        spoiled += bool(workslike_checker.check(rough, rough))
    assert spoiled >= 40, spoiled
    for seed in range(30):
        made = contradict.contradict(products.generate(seed).model, random.Random(seed))
        if made:
            assert workslike_checker.check(made[0], made[0]), (seed, made[1])
