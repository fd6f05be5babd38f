// cli_flags_output.cpp - the flags of what a run writes and prints: headless images, picks
// and measurements, the reports (--stats, --tree, --distance, --properties, --export) and
// the benchmark.
#include "app/cli_flags.h"

#include "app/cli_flag_tables.h"

namespace app::flag_tables {

std::vector<Flag> headlessFlags(const Options& d) {
    return {
        headless({"--frames", "N",
                  "frames to render headless" + byDefault(d.frames) + "; files hold the last one",
                  [](Options& o, auto& v) { o.frames = parseCount("--frames", v, 1, 1000000); }}),
        headless(text("--screenshot", "FILE", "write the last frame's colour image as PNG",
                      &Options::screenshot)),
        {"--thumbnail", "SIZE",
         "write a file manager's preview: a SIZExSIZE PNG of the model, fitted, to the "
         "--screenshot file (written whole or not at all), by a child process given up on after "
         "--thumbnail-timeout or past --thumbnail-memory; implies --headless and one frame",
         [](Options& o, auto& v) {
             o.thumbnail.size = parseCount("--thumbnail", v, 1, 4096);
             o.headless = true;
         }},
        {"--thumbnail-timeout", "SECONDS",
         "--thumbnail: give up after SECONDS, above 0" + byDefault(d.thumbnail.seconds),
         [](Options& o, auto& v) {
             o.thumbnail.seconds = parseNumber("--thumbnail-timeout", v, 3600.0f, "seconds");
             if (o.thumbnail.seconds <= 0.0f)
                 throw UsageError("--thumbnail-timeout expects seconds above 0, not '" + v + "'");
         }},
        {"--thumbnail-memory", "MIB",
         "--thumbnail: give up past MIB MiB of data memory in any one process (its heap and "
         "private maps)" +
             byDefault(d.thumbnail.memoryMib),
         [](Options& o, auto& v) {
             o.thumbnail.memoryMib = parseCount("--thumbnail-memory", v, 16, 1u << 20);
         }},
        headless(
            text("--id-image", "FILE",
                 "write the last frame's part IDs: W*H little-endian uint32, row-major, top row "
                 "first, "
                 "0xFFFFFFFF where no part is",
                 &Options::idImage)),
        headless(
            {"--pick", "X,Y",
             "headless: pick the part at pixel X,Y (top-left origin) and print one JSON line "
             "{x,y,part,object,local_part,name,path,depth} (name: the object's, path: its node "
             "path from the root; all but x,y null on background; CAD files add face, the "
             "part's B-rep face); repeatable; the last point "
             "stays hovered in the images",
             [](Options& o, auto& v) { o.picks.push_back(parsePixel("--pick", v)); }}),
        headless({"--select", "X,Y",
                  "headless: select the part at pixel X,Y as a click there would",
                  [](Options& o, auto& v) { o.selects = {parsePixel("--select", v)}; }}),
        headless({"--select-rect", "X0,Y0,X1,Y1",
                  "headless: select every part visible in the pixel rectangle (corners included) "
                  "as a box selection would, and print one JSON line {rect,parts,count}",
                  [](Options& o, auto& v) { o.selectRect = parseRect("--select-rect", v); }}),
        headless({"--measure", "X0,Y0,X1,Y1",
                  "headless: pick both pixels and print one JSON line "
                  "{p0,p1,distance,delta,parts}: the world points under them (from the depth the "
                  "pick reads), their distance and dX,dY,dZ, and the unique part at each; null "
                  "where a pixel shows no part",
                  [](Options& o, auto& v) { o.measure = parseMeasure(v); }}),
        headless(
            {"--face-info", "X,Y",
             "headless: pick the pixel and print one JSON line of its part's face "
             "{part,object,face,surface,area,...,bbox}: for CAD files the B-rep surface type "
             "(plane, cylinder, cone, sphere, torus, bspline, bezier, revolution, extrusion, "
             "offset, other) and exact area, with normal and d for planes, radius and axis for "
             "cylinders, radius and center for spheres; for other parts surface mesh and the "
             "area of its triangles; {\"part\":null} on background; repeatable",
             [](Options& o, auto& v) { o.faceInfos.push_back(parsePixel("--face-info", v)); }}),
        headless(
            {"--edge-info", "X,Y",
             "headless: pick the pixel and print one JSON line of the B-rep edge of its "
             "part's face drawn nearest it, within a few pixels: {x,y,part,object,edge,curve,"
             "length,...,start,end,closed} with curve line, circle, ellipse, bspline or other, "
             "its exact length, radius, diameter, center and axis for circles, direction for "
             "lines; \"edge\":null away from every edge, on background or without a B-rep; "
             "repeatable",
             [](Options& o, auto& v) { o.edgeInfos.push_back(parsePixel("--edge-info", v)); }}),
        headless({"--hide", "ID,...", "headless: do not draw these unique parts (nor pick them)",
                  [](Options& o, auto& v) { o.hide = parseIds("--hide", v); }}),
        headless({"--isolate", "ID,...", "headless: draw only these unique parts",
                  [](Options& o, auto& v) { o.isolate = parseIds("--isolate", v); }}),
        headless(
            on("--visible-parts",
               "headless: print one JSON line {count,parts} of the unique parts the last frame "
               "shows, counted on the GPU; with --benchmark every frame counts them",
               &Options::visibleParts)),
        {"--census", "VIEWSxSIZE",
         "headless visibility census: render the model from VIEWS directions spread evenly "
         "over a sphere (orthographic, each SIZExSIZE pixels, holding the bounding sphere) "
         "with --hide, --isolate, --section and --explode applied, count every unique part's "
         "pixels on the GPU and print one JSON line per part "
         "{part,object,name,path,pixels,views,largest_share}, then one summary line (parts "
         "and solids never seen, their triangles and share); with --benchmark time it "
         "instead; implies --headless",
         [](Options& o, auto& v) {
             o.census = parseCensus(v);
             o.headless = true;
         }},
        headless(text("--census-csv", "FILE", "--census: also write the part lines as CSV",
                      &Options::censusCsv)),
        headless({"--census-export", "FILE",
                  "--census: write what was seen: FILE.glb the seen parts (glTF); FILE.step or "
                  ".stp the solids with a seen face, through Open CASCADE with the source's "
                  "names, colours and assembly (CAD models only)",
                  [](Options& o, auto& v) {
                      if (!v.ends_with(".glb") && !censusExportsStep(v))
                          throw UsageError("--census-export writes .glb, .step or .stp, not '" + v +
                                           "'");
                      o.censusExport = v;
                  }}),
    };
}

std::vector<Flag> reportFlags(const Options&) {
    return {
        on("--stats",
           "print the scene's statistics as one JSON object (objects, geometries, parts, "
           "triangles, load_ms, ID buffer bytes) and, for the chosen renderer and mode, draws, "
           "pipelines and the bytes of each buffer; then exit. With --headless it renders "
           "first and adds first_frame_ms (from creating the device to the first frame's "
           "fence) and pipeline_cache (hit, miss, off, or rejected: why); null without",
           &Options::stats),
        on("--tree",
           "print the scene's assembly tree as one JSON object, nested "
           "{name,children} down to each object's leaf {name,object,parts:[first unique "
           "part, count]} (STEP/IGES products and instances, glTF nodes, procedural groups, "
           "copies); then exit",
           &Options::tree),
        {"--distance", "A,B",
         "print one JSON line {distance,p0,p1,source,...,unit}: the minimum distance between "
         "unique parts A and B and its closest points, exact from the B-rep for CAD files "
         "(source brep), from the triangles otherwise (mesh); where both are circles or "
         "cylinders also center_distance, axis_angle (degrees) and, for parallel axes, "
         "axis_distance; where one is a plane, point_to_plane (the other's centre, signed "
         "along the plane's outward normal); without --headless nothing is rendered and idview "
         "exits",
         [](Options& o, auto& v) { o.distance = parseDistance(v); }},
        {"--properties", "OBJECT|all",
         "print one JSON line {object,volume,area,center,bbox:{min,max,size},closed,unit} of "
         "the object (a solid of a CAD file: exact, from the B-rep; meshes: from triangles, "
         "volume 0 unless they close); all: one line per object and their sum "
         "{object:\"all\",objects,...}; without --headless nothing is rendered and idview "
         "exits",
         [](Options& o, auto& v) {
             o.propertiesAll = v == "all";
             if (!o.propertiesAll)
                 o.propertiesObject = parseCount("--properties", v, 0, 0xFFFFFFFEu);
         }},
        text("--export", "FILE", "write the scene (after copies) as binary glTF and exit",
             &Options::exportPath),
    };
}

std::vector<Flag> benchmarkFlags(const Options&) {
    return {
        {"--benchmark", nullptr,
         "headless: time every renderer x mode x culling mode and the floors (no-id, "
         "no-id-mesh with mesh techniques); defaults 2560x1440, "
         "--msaa 4, --copies 3, --frames 200 (each flag overrides)",
         [](Options& o, auto&) { o.benchmark = o.headless = true; }},
        headless(text("--benchmark-out", "FILE",
                      "write the benchmark as JSON (CSV when FILE ends in .csv)",
                      &Options::benchmarkOut)),
    };
}

} // namespace app::flag_tables
