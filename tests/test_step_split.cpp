// test_step_split.cpp - the STEP splitter (scene/step/step_split.h) on handmade texts: the
// lexer's index (strings, comments, complex and multi-line records, sparse ids), the texts it
// refuses in one line (and every cut of a file, without a crash or a hang), and the splitting
// rules: layouts, boxes, what the skeleton keeps and drops, what a piece holds, and the files
// that are not split. Open CASCADE reads real splits in test_step_split_occt.cpp.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/step/step_index.h"
#include "scene/step/step_split.h"
#include "step_split_files.h"

namespace {

using namespace scene::step;
using steptest::stepFile;
using steptest::TempFile;

std::vector<uint64_t> idsOf(const StepIndex& index, std::span<const uint32_t> records) {
    std::vector<uint64_t> ids;
    for (uint32_t r : records) ids.push_back(r == kNoRecord ? 0 : index.idOf(r));
    return ids;
}

TEST(StepLexer, IndexesRecordsWhateverTheirStringsCommentsAndLayout) {
    const std::string text =
        stepFile("#30 = NAMED('a;b#1(c)'' /*no*/\nsecond line', #10, ( #20 , #5 ) ) ;\n"
                 "/* a comment with #99 ; ' */ #10=\n"
                 "  PLAIN ( 1.E-07 , .T. , $ , * , LENGTH_MEASURE( 2.5 ) , /* in */ #5 );\n"
                 "#5 = ( A_PART ( #10 ) B_PART ( 'x)' ) /* ) */ );\n"
                 "#20 = EMPTY ( ) ;\n"
                 "#7 = MISSING(#1000);\n");
    StepIndex index;
    const auto refused = lexStep(text, index);
    ASSERT_FALSE(refused) << *refused;
    ASSERT_EQ(index.size(), 5u);
    EXPECT_EQ(idsOf(index, std::vector<uint32_t>{0, 1, 2, 3, 4}),
              (std::vector<uint64_t>{30, 10, 5, 20, 7}));
    EXPECT_EQ(index.maxId, 30u);
    EXPECT_EQ(index.text.substr(index.dataBegin, 5), "DATA;");
    EXPECT_EQ(index.textOf(0),
              "#30 = NAMED('a;b#1(c)'' /*no*/\nsecond line', #10, ( #20 , #5 ) ) ;");
    EXPECT_EQ(index.textOf(1).substr(0, 6), "#10=\n ");
    EXPECT_EQ(index.textOf(1).substr(index.textOf(1).size() - 5), "#5 );");
    EXPECT_EQ(index.types.name(index.type[0]), "NAMED");
    EXPECT_EQ(index.types.name(index.type[2]), "(A_PART B_PART)");
    EXPECT_TRUE(index.types.isComplex(index.type[2]));
    EXPECT_EQ(idsOf(index, index.refsOf(0)), (std::vector<uint64_t>{10, 20, 5}));
    EXPECT_EQ(idsOf(index, index.refsOf(1)), (std::vector<uint64_t>{5}));
    EXPECT_EQ(idsOf(index, index.refsOf(2)), (std::vector<uint64_t>{10}));
    EXPECT_TRUE(index.refsOf(3).empty());
    ASSERT_EQ(index.refsOf(4).size(), 1u);
    EXPECT_EQ(index.refsOf(4)[0], kNoRecord); // kept: Open CASCADE warns of it itself
    EXPECT_EQ(index.missingRefs, 1u);
}

// Ids far apart are found through a sorted list instead of a table.
TEST(StepLexer, FindsSparseIds) {
    const std::string text = stepFile("#9000000000 = A(#5, #77);\n#5 = B(#9000000000);\n"
                                      "#77 = C(#5);\n");
    StepIndex index;
    ASSERT_FALSE(lexStep(text, index));
    EXPECT_EQ(index.maxId, 9000000000u);
    EXPECT_EQ(idsOf(index, index.refsOf(0)), (std::vector<uint64_t>{5, 77}));
    EXPECT_EQ(idsOf(index, index.refsOf(1)), (std::vector<uint64_t>{9000000000u}));
    EXPECT_EQ(idsOf(index, index.refsOf(2)), (std::vector<uint64_t>{5}));
}

TEST(StepLexer, RefusesWhatItDoesNotTakeInOneLine) {
    const std::string head = "ISO-10303-21;\nHEADER;\nENDSEC;\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {head + "DATA;\n#1 = A('abc", "the file ends inside a string (record #1)"},
        {head + "DATA;\n#1 = A(1); /* abc", "the file ends inside a comment"},
        {head + "DATA;\n#1 = A(1)\n#2 = B(2);\nENDSEC;\n", "record #1 does not end with ';'"},
        {head + "DATA;\n#1 = A(1;\n#2 = B(2);\n", "record #1 does not end (';'"},
        {head + "DATA;\n#1 = A(1);\n", "the DATA section does not end (no ENDSEC;)"},
        {head + "DATA;\n#1 = A(1, (2);\n", "record #1 does not end (';'"},
        {head + "DATA;\n#1 = A(1, (2)", "the file ends inside record #1"},
        {head + "DATA;\nENDSEC;\nDATA;\n#2 = B();\nENDSEC;\nEND-ISO-10303-21;\n",
         "a second DATA section"},
        {head + "ANCHOR;\n<a> = #1;\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n",
         "an ANCHOR section (edition 3) before DATA"},
        {head + "DATA('x',('y'));\nENDSEC;\nEND-ISO-10303-21;\n", "DATA section with parameters"},
        {head + "DATA;\n#1 = A();\n#1 = B();\n#2 = C(#1);\nENDSEC;\nEND-ISO-10303-21;\n",
         "#1 is defined twice and referenced"},
        {head + "DATA;\n#1 = A(#);\nENDSEC;\nEND-ISO-10303-21;\n", "a bad reference"},
        {head + "DATA;\n#1 A(1);\nENDSEC;\nEND-ISO-10303-21;\n", "'=' expected after #1"},
        {head + "DATA;\n#1 = ( );\nENDSEC;\nEND-ISO-10303-21;\n", "complex record #1 is empty"},
        {head + "DATA;\n#1 = 5;\nENDSEC;\nEND-ISO-10303-21;\n", "#1 is not TYPE(...)"},
        {head + "DATA;\nFOO;\nENDSEC;\nEND-ISO-10303-21;\n", "unexpected text in the DATA"},
        {head + "DATA;\nENDSEC;\n", "the file ends without END-ISO-10303-21;"},
        {head, "no DATA section"},
        {"", "no DATA section"},
    };
    for (const auto& [text, reason] : cases) {
        StepIndex index;
        const auto refused = lexStep(text, index);
        ASSERT_TRUE(refused) << text;
        EXPECT_NE(refused->find(reason), std::string::npos) << *refused << "\n" << text;
        EXPECT_EQ(refused->find('\n'), std::string::npos) << *refused;
    }
    StepIndex twice; // an id defined twice that nothing references does no harm
    EXPECT_FALSE(
        lexStep(head + "DATA;\n#1 = A();\n#1 = B();\nENDSEC;\nEND-ISO-10303-21;\n", twice));
}

// Cut anywhere before its last ';', a file is refused (never a crash or a hang); whole, it is
// taken.
TEST(StepLexer, RefusesEveryCutOfAFile) {
    const std::string text = stepFile("#1 = A('it''s; (#2)', /* #3 */ #2);\n"
                                      "#2 = ( B(1.5) C((#1, $)) );\n");
    for (size_t size = 0; size < text.rfind(';'); ++size) {
        const std::string cut = text.substr(0, size);
        StepIndex index;
        EXPECT_TRUE(lexStep(cut, index)) << "cut at " << size;
    }
    StepIndex index;
    EXPECT_FALSE(lexStep(text, index));
}

// One product whose representation holds a placement, two solids (a face shared between
// them, a void that meets a face again through an ORIENTED_FACE) and a surface model (a face
// of its own and one of the first solid's); a second representation of faces without
// vertices; styles on geometry and on the placement; records that use the geometry. The
// faces' placement shares its point and directions with the representation's.
std::string face(int id, const char* xyz) {
    const std::string n = std::to_string(id);
    auto at = [&](int k) { return "#" + std::to_string(id + k); };
    return "#" + n + " = ADVANCED_FACE('',(" + at(1) + "),#90,.T.);\n" + at(1) +
           " = FACE_BOUND(''," + at(2) + ",.T.);\n" + at(2) + " = VERTEX_LOOP(''," + at(3) +
           ");\n" + at(3) + " = VERTEX_POINT(''," + at(4) + ");\n" + at(4) +
           " = CARTESIAN_POINT('',(" + xyz + "));\n";
}

std::string handmade() {
    return "#1 = APPLICATION_CONTEXT('test');\n#2 = PRODUCT_CONTEXT('',#1,'mechanical');\n"
           "#3 = PRODUCT('part','part','',(#2));\n#4 = PRODUCT_DEFINITION_FORMATION('','',#3);\n"
           "#5 = PRODUCT_DEFINITION_CONTEXT('part definition',#1,'design');\n"
           "#6 = PRODUCT_DEFINITION('design','',#4,#5);\n"
           "#7 = PRODUCT_DEFINITION_SHAPE('','',#6);\n"
           "#8 = SHAPE_DEFINITION_REPRESENTATION(#7,#10);\n"
           "#9 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) REPRESENTATION_CONTEXT('','') );\n"
           "#10 = ADVANCED_BREP_SHAPE_REPRESENTATION('rep',(#11,#20,#30,#40),#9);\n"
           "#11 = AXIS2_PLACEMENT_3D('',#12,#13,#14);\n#12 = CARTESIAN_POINT('',(0.,0.,0.));\n"
           "#13 = DIRECTION('',(0.,0.,1.));\n#14 = DIRECTION('',(1.,0.,0.));\n"
           "#20 = MANIFOLD_SOLID_BREP('a',#21);\n#21 = CLOSED_SHELL('',(#500,#510));\n"
           "#30 = BREP_WITH_VOIDS('b',#31,(#32));\n#31 = CLOSED_SHELL('',(#510,#520));\n"
           "#32 = ORIENTED_CLOSED_SHELL('',*,#33,.F.);\n#33 = CLOSED_SHELL('',(#530,#34));\n"
           "#34 = ORIENTED_FACE('',*,#520,.F.);\n"
           "#40 = SHELL_BASED_SURFACE_MODEL('',(#41));\n#41 = OPEN_SHELL('',(#540,#500));\n"
           "#90 = PLANE('',#91);\n#91 = AXIS2_PLACEMENT_3D('',#12,#13,#14);\n" +
           face(500, "-1.5,0.,0.") + face(510, "2.E+01,-3.,0.") + face(520, "+3.,4.,-0.25") +
           face(530, "0.,0.,7.") + face(540, "1.,1.,1.") +
           "#70 = STYLED_ITEM('',(#71),#20);\n#71 = PRESENTATION_STYLE_ASSIGNMENT((#72));\n"
           "#72 = COLOUR_RGB('',1.,0.,0.);\n#74 = STYLED_ITEM('',(#71),#540);\n"
           "#75 = STYLED_ITEM('',(#71),#11);\n"
           "#76 = MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION('',(#70,#74,#75),#9);\n"
           "#77 = PRESENTATION_LAYER_ASSIGNMENT('layer','',(#20,#30));\n"
           "#78 = DRAUGHTING_MODEL('',(#70),#9);\n"
           "#79 = GEOMETRIC_ITEM_SPECIFIC_USAGE('','',#80,#10,#530);\n"
           "#80 = SHAPE_ASPECT('','',#7,.F.);\n"
           "#100 = MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#101),#9);\n"
           "#101 = FACE_BASED_SURFACE_MODEL('',(#102));\n"
           "#102 = CONNECTED_FACE_SET('',(#103));\n#103 = FACE_SURFACE('',(),#90,.T.);\n";
}

bool holds(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

TEST(StepSplit, LaysOutBoxesAndCutsAHandmadeFile) {
    const TempFile file("handmade.step", stepFile(handmade()));
    const StepSplit split(file.path());
    ASSERT_FALSE(split.notSplit()) << split.notSplit()->reason;
    ASSERT_EQ(split.pieces().size(), 2u);
    const Piece& first = split.pieces()[0];
    EXPECT_EQ(first.rep, 10u);
    EXPECT_EQ(first.layout.solids, 2u);
    EXPECT_TRUE(first.layout.split);
    EXPECT_TRUE(first.layout.freeFaces);
    EXPECT_EQ(first.layout.objectFaces, (std::vector<uint32_t>{2, 3, 2}));
    EXPECT_EQ(first.layout.faces(), 7u);
    EXPECT_TRUE(first.hasBox);
    EXPECT_EQ(first.boxMin, (std::array<double, 3>{-1.5, -3.0, -0.25}));
    EXPECT_EQ(first.boxMax, (std::array<double, 3>{20.0, 4.0, 7.0}));
    const Piece& second = split.pieces()[1];
    EXPECT_EQ(second.rep, 100u);
    EXPECT_EQ(second.layout.objectFaces, (std::vector<uint32_t>{1}));
    EXPECT_FALSE(second.layout.split);
    EXPECT_EQ(second.layout.solids, 0u);
    EXPECT_FALSE(second.hasBox);
    EXPECT_EQ(first.dummySet, 547u); // above #544, the largest
    EXPECT_EQ(second.dummySet, 550u);
    EXPECT_EQ(split.entities(), 64u);

    const std::string skeleton = split.skeleton();
    EXPECT_TRUE(holds(skeleton, "#10=ADVANCED_BREP_SHAPE_REPRESENTATION('rep',(#11,#547),#9);"));
    EXPECT_TRUE(holds(skeleton, "#545=CARTESIAN_POINT('',(-1.5,-3.,-0.25));"));
    EXPECT_TRUE(holds(skeleton, "#546=CARTESIAN_POINT('',(2.E+01,4.,7.));"));
    EXPECT_TRUE(holds(skeleton, "#547=GEOMETRIC_SET('',(#545,#546));"));
    EXPECT_TRUE(holds(skeleton, "#548=CARTESIAN_POINT('',(0.,0.,0.));"));
    EXPECT_TRUE(holds(skeleton, "#100=MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#550),#9);"));
    EXPECT_TRUE(holds(skeleton, "#76=MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION("
                                "'',(#75),#9);"));
    for (const char* kept : {"#8 = SHAPE_DEFINITION", "#75 = STYLED_ITEM", "#72 = COLOUR_RGB",
                             "#12 = CARTESIAN_POINT", "#11 = AXIS2", "#1 = APPLICATION_CONTEXT"})
        EXPECT_TRUE(holds(skeleton, kept)) << kept;
    for (const char* left : {"#20 =", "#21 =", "#40 =", "#90 =", "#500 =", "#504 =", "#70 =",
                             "#74 =", "#77 =", "#78 =", "#79 =", "#80 =", "#101 ="})
        EXPECT_FALSE(holds(skeleton, left)) << left;
    EXPECT_EQ(skeleton.substr(0, 13), "ISO-10303-21;");
    EXPECT_EQ(skeleton.substr(skeleton.size() - 26), "ENDSEC;\nEND-ISO-10303-21;\n");

    const std::string piece = split.pieceText(0);
    EXPECT_EQ(piece.size(), first.bytes);
    for (const char* kept : {"#10 = ADVANCED_BREP", "#9 = (", "#11 =", "#20 =", "#34 =", "#41 =",
                             "#504 =", "#544 =", "#70 =", "#74 =", "#72 ="})
        EXPECT_TRUE(holds(piece, kept)) << kept;
    for (const char* left : {"#75 =", "#76 =", "#77 =", "#78 =", "#79 =", "#100 =", "#8 ="})
        EXPECT_FALSE(holds(piece, left)) << left;
    EXPECT_TRUE(holds(piece, "#552=SHAPE_DEFINITION_REPRESENTATION(#551,#10);"));
    EXPECT_TRUE(holds(piece, "#553=MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION("
                             "'',(#70,#74),#9);"));
    const std::string other = split.pieceText(1);
    EXPECT_EQ(other.size(), second.bytes);
    EXPECT_TRUE(holds(other, "#103 = FACE_SURFACE"));
    EXPECT_FALSE(holds(other, "#20 ="));
    EXPECT_FALSE(holds(other, "MECHANICAL_DESIGN"));
}

// A style for one instance (Open CASCADE's instance colours) on the whole of a shape stays in
// the skeleton, moved onto the set that stands for the shape, and out of the piece.
TEST(StepSplit, KeepsAnInstanceStyleInTheSkeletonOnItsSet) {
    const TempFile file("instance.step",
                        stepFile(handmade() +
                                 "#121 = OVER_RIDING_STYLED_ITEM('o',(#122),#101,#70);\n"
                                 "#122 = PRESENTATION_STYLE_BY_CONTEXT((#72),#8);\n"));
    const StepSplit split(file.path());
    ASSERT_FALSE(split.notSplit()) << split.notSplit()->reason;
    const std::string skeleton = split.skeleton();
    EXPECT_TRUE(holds(skeleton, "#121=STYLED_ITEM('o',(#122),#550);"));
    EXPECT_TRUE(holds(skeleton, "#122 = PRESENTATION_STYLE_BY_CONTEXT"));
    for (size_t k = 0; k < split.pieces().size(); ++k) {
        EXPECT_FALSE(holds(split.pieceText(k), "#121 =")) << k;
        EXPECT_FALSE(holds(split.pieceText(k), "#122 =")) << k;
    }
}

TEST(StepSplit, LeavesWholeWhatTheSkeletonCouldNotStandFor) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"#110 = SHAPE_REPRESENTATION('',(#20),#9);\n",
         "#20 (MANIFOLD_SOLID_BREP) is in two representations"},
        {"#111 = SOME_USE('',#30);\n", "#30 (BREP_WITH_VOIDS) is used by #111 (SOME_USE)"},
        {"#112 = CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM('',(#71),#500,#70,(#8));\n",
         "styles that depend on the assembly context"},
        {"#113 = SHAPE_REPRESENTATION('',(#101,#114),#9);\n#114 = MAPPED_ITEM('',#115,#11);\n",
         "beside a mapped item"},
        {"#116 = SHAPE_REPRESENTATION('',(#117),#9);\n#117 = CURVE_USE('',#503);\n",
         "#116 (SHAPE_REPRESENTATION) uses the geometry of a solid"},
        {"#118 = MANIFOLD_SOLID_BREP('',#21);\n", "#118 (MANIFOLD_SOLID_BREP) is in no repr"},
        {"#119 = STYLED_ITEM('',(#120),#500);\n#120 = SOME_STYLE(#100);\n",
         "the piece of #10 (ADVANCED_BREP_SHAPE_REPRESENTATION) would hold #101"},
        {"#121 = OVER_RIDING_STYLED_ITEM('',(#122),#500,#70);\n"
         "#122 = PRESENTATION_STYLE_BY_CONTEXT((#72),#8);\n",
         "styles that depend on the assembly context (#121 (OVER_RIDING_STYLED_ITEM) on #500 "
         "(ADVANCED_FACE), a part of its representation's shape)"},
        {"#123 = STYLED_ITEM('',(#122),#20);\n#122 = PRESENTATION_STYLE_BY_CONTEXT((#72),#8);\n",
         "on #20 (MANIFOLD_SOLID_BREP), a part of its representation's shape"},
    };
    for (const auto& [extra, reason] : cases) {
        const TempFile file("refused.step", stepFile(handmade() + extra));
        const StepSplit split(file.path());
        ASSERT_TRUE(split.notSplit()) << extra;
        EXPECT_NE(split.notSplit()->reason.find(reason), std::string::npos)
            << split.notSplit()->reason;
        EXPECT_TRUE(split.pieces().empty());
        EXPECT_THROW(split.skeleton(), std::logic_error);
    }
    for (const std::string data : {"", "#1 = CARTESIAN_POINT('',(0.,0.,0.));\n"}) {
        const TempFile file("empty.step", stepFile(data));
        const StepSplit split(file.path());
        ASSERT_TRUE(split.notSplit());
        EXPECT_EQ(split.notSplit()->reason, "no solids to split");
    }
    const std::string whole = stepFile(handmade());
    const TempFile cut("cut.step", whole.substr(0, whole.find("'part'") + 3));
    const StepSplit split(cut.path());
    ASSERT_TRUE(split.notSplit());
    EXPECT_EQ(split.notSplit()->reason, "the file ends inside a string (record #3)");
    EXPECT_THROW(StepSplit("/nonexistent/file.step"), std::runtime_error);
}

} // namespace
