// A plain MaxRects beside FabGuide in tests/bench/saw_benchmark.py: npm's maxrects-packer, installed by
// tests/bench/build_maxrects.sh into FOLDER, with its defaults (max-edge rule, its own sort), one run.
//     node maxrects.js FOLDER < groups.json
// Reads [{"sheet": [w, h], "items": [[w, h, copies, fixed], ...]}, ...] (kerf already added) and prints the bins
// each group needs, as JSON; an item too large for its sheet is an error.
const path = require("path");

let input = "";
process.stdin.on("data", (chunk) => (input += chunk));
process.stdin.on("end", async () => {
    const { MaxRectsPacker, Rectangle } = await import(
        path.resolve(process.argv[2], "node_modules", "maxrects-packer", "dist", "maxrects-packer.mjs"));
    const bins = JSON.parse(input).map(({ sheet, items }) => {
        const packer = new MaxRectsPacker(sheet[0], sheet[1], 0,
                                          { smart: false, pot: false, square: false, allowRotation: true });
        const rects = [];
        for (const [w, h, copies, fixed] of items)
            for (let k = 0; k < copies; ++k)
                rects.push(new Rectangle(w, h, 0, 0, false, !fixed));
        packer.addArray(rects);
        if (packer.bins.some((bin) => bin.rects.some((r) => r.oversized)))
            throw new Error("an item larger than its sheet");
        return packer.bins.length;
    });
    console.log(JSON.stringify(bins));
});
