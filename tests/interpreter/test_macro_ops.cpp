// Custom Macro B through the interpreter (FANUC 0i/16i/18i/30i "Custom macro"; reference
// dialects.md §3.7). tests/interpreter/test_macro.cpp checks the evaluator on its own; here every
// operator, function and rule is run inside programs: statements assign, the results come back as
// positions of moves, conditions through IF [..] THEN, G65 arguments and local levels through real
// calls, WHILE/DO/END and GOTO through the block loop, alarms as alarm events.
//
// How a value is read back: `#199=<expression>`, then `G0 X-777777. Z<k>.` (a sentinel) and
// `G0 X#199 Z<k>.`; the second move's X is the value, or the sentinel when #199 is vacant (FANUC:
// "when an undefined variable is quoted, the address itself is ignored"). Every expected number is
// worked out by hand in the comment or the table next to it.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr double kSentinel = -777777;

// Every run is fanuc-mill with bare_setup (tests/interpreter/interpreter_fixture.hpp), IS-B: X10 = 0.010 mm.

// Runs `prelude`, then each expression into #199 and out through a tagged move (tags 1, 2, ...).
// Result per expression: its value, nullopt when vacant; a missing move fails the test.
std::vector<std::optional<double>> values(const std::string& prelude, const std::vector<std::string>& expressions) {
    std::string text = "O1\nG90 G0 X0. Y0. Z0.\n" + prelude;
    for (std::size_t i = 0; i < expressions.size(); ++i) {
        const std::string tag = std::to_string(i + 1) + ".";
        text += "#199=" + expressions[i] + "\nG0 X-777777. Z" + tag + "\nG0 X#199 Z" + tag + "\n";
    }
    text += "M30\n";
    const Run r = run_bare(text);
    require_clean(r);
    std::vector<std::optional<double>> out;
    for (std::size_t i = 0; i < expressions.size(); ++i) {
        const auto x = x_at(r, static_cast<double>(i + 1));
        INFO(expressions[i]);
        REQUIRE(x.has_value());
        out.push_back(*x == kSentinel ? std::nullopt : x);
    }
    return out;
}

// Each condition through `IF [<condition>] THEN #198=1` (after #198=0); true when #198 became 1.
std::vector<bool> conditions(const std::string& prelude, const std::vector<std::string>& list) {
    std::string text = "O1\nG90 G0 X0. Y0. Z0.\n" + prelude;
    for (std::size_t i = 0; i < list.size(); ++i)
        text += "#198=0\nIF [" + list[i] + "] THEN #198=1\nG0 X#198 Z" + std::to_string(i + 1) + ".\n";
    text += "M30\n";
    const Run r = run_bare(text);
    require_clean(r);
    std::vector<bool> out;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const auto x = x_at(r, static_cast<double>(i + 1));
        INFO(list[i]);
        REQUIRE(x.has_value());
        out.push_back(*x == 1.0);
    }
    return out;
}

struct Case {
    std::string text;
    double expected;
};

void check_values(const std::vector<Case>& cases, const std::string& prelude = "") {
    std::vector<std::string> expressions;
    for (const Case& c : cases) expressions.push_back(c.text);
    const auto got = values(prelude, expressions);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        INFO(cases[i].text);
        REQUIRE(got[i].has_value());
        CHECK(*got[i] == Approx(cases[i].expected).margin(1e-9));
    }
}

}  // namespace

// --- operators -------------------------------------------------------------------------------------

// FANUC precedence: functions, then * / AND MOD, then + - OR XOR; brackets first.
TEST_CASE("arithmetic and logical operators in statements", "[macro]") {
    check_values({
        {"1+2", 3},                // 3
        {"5-7", -2},               // −2
        {"2*3.5", 7},              // 7
        {"7/2", 3.5},              // 3.5
        {"1+2*3", 7},              // * before +: 1 + 6
        {"[1+2]*3", 9},            // brackets first: 3·3
        {"10-4-3", 3},             // left to right: (10 − 4) − 3
        {"-[2*3]", -6},            // unary minus of a bracket
        {"10 MOD 3", 1},           // 10 = 3·3 + 1
        {"-10 MOD 3", -1},         // 30i MOD: the sign of the dividend, −10 = 3·(−3) − 1
        {"5 AND 3", 1},            // 101 & 011 = 001
        {"5 OR 3", 7},             // 101 | 011 = 111
        {"5 XOR 3", 6},            // 101 ^ 011 = 110
        {"1 OR 2 AND 3", 3},       // AND is multiplicative: 1 | (2 & 3) = 1 | 2 = 3
    });
}

TEST_CASE("every comparison in IF [..] THEN", "[macro]") {
    const std::vector<std::string> list = {"1 EQ 1", "1 EQ 2", "1 NE 2", "2 NE 2", "3 GT 2", "2 GT 2",
                                           "2 GE 2", "1 GE 2", "1 LT 2", "2 LT 2", "2 LE 2", "3 LE 2",
                                           "[1 EQ 1] AND [2 EQ 2]", "[1 EQ 1] AND [2 EQ 3]", "[1 EQ 2] OR [2 EQ 2]",
                                           "[1 EQ 2] OR [2 EQ 3]"};
    const std::vector<bool> expected = {true, false, true, false, true, false, true, false,
                                        true, false, true, false, true, false, true, false};
    const auto got = conditions("", list);
    for (std::size_t i = 0; i < list.size(); ++i) {
        INFO(list[i]);
        CHECK(got[i] == expected[i]);
    }
}

// --- functions ---------------------------------------------------------------------------------------

// Angles in degrees; the table's values by hand: sin 30° = 0.5, cos 60° = 0.5, tan 45° = 1,
// asin 0.5 = 30°, acos 0.5 = 60°; ATAN[a]/[b] and ATAN[a,b] with NAT = 0 (0..360°):
// atan2(1, 1) = 45°, atan2(−1, −1) = −135° → 225°, atan2(1, −1) = 135°; ATAN[1] = 45° (one argument).
TEST_CASE("trigonometric functions", "[macro]") {
    check_values({
        {"SIN[30]", 0.5},
        {"SIN[-90]", -1},
        {"COS[60]", 0.5},
        {"COS[180]", -1},
        {"TAN[45]", 1},
        {"TAN[-45]", -1},
        {"ASIN[0.5]", 30},
        {"ACOS[0.5]", 60},
        {"ACOS[-1]", 180},
        {"ATAN[1]/[1]", 45},
        {"ATAN[-1]/[-1]", 225},
        {"ATAN[1,-1]", 135},
        {"ATAN[1]", 45},
    });
}

// sqrt 16 = 4; |−3.5| = 3.5; BIN[291]: 291 = 0x123 → 123; BCD[123] = 0x123 = 291;
// ln 1 = 0; e^0 = 1; ln e² = 2; 2^10 = 1024; ADP of a value with a point is the value (1.5).
TEST_CASE("SQRT ABS BIN BCD LN EXP POW ADP", "[macro]") {
    check_values({
        {"SQRT[16]", 4},
        {"SQRT[2]*SQRT[2]", 2},
        {"ABS[-3.5]", 3.5},
        {"ABS[3.5]", 3.5},
        {"BIN[291]", 123},
        {"BCD[123]", 291},
        {"LN[1]", 0},
        {"EXP[0]", 1},
        {"LN[EXP[2]]", 2},
        {"POW[2,10]", 1024},
        {"ADP[1.5]", 1.5},
    });
}

// FANUC: ROUND rounds half away from zero, FIX discards the fraction (toward zero), FUP raises
// the absolute value to the next integer (away from zero):
//   ROUND[1.5] = 2, ROUND[−1.5] = −2, ROUND[−1.4] = −1, ROUND[2.5] = 3
//   FIX[1.9] = 1, FIX[−1.2] = −1, FIX[−1.9] = −1
//   FUP[1.2] = 2, FUP[−1.2] = −2, FUP[2] = 2, FUP[−2] = −2
TEST_CASE("ROUND FIX FUP of positive and negative numbers", "[macro]") {
    check_values({
        {"ROUND[1.5]", 2},
        {"ROUND[-1.5]", -2},
        {"ROUND[-1.4]", -1},
        {"ROUND[2.5]", 3},
        {"FIX[1.9]", 1},
        {"FIX[-1.2]", -1},
        {"FIX[-1.9]", -1},
        {"FUP[1.2]", 2},
        {"FUP[-1.2]", -2},
        {"FUP[2]", 2},
        {"FUP[-2]", -2},
    });
}

// [FANUC] "When the ROUND function is used in NC statement addresses, it rounds at the least input
// increment of the address" (the manual's example): #1 = 1.2345, #2 = 2.3456, IS-B 0.001 mm:
// X[ROUND[#1]+ROUND[#2]] = 1.235 + 2.346 = 3.581 (not 1 + 2 = 3).
TEST_CASE("ROUND in an NC address rounds to the least input increment", "[macro]") {
    const Run r = run_bare("O1\n#1=1.2345\n#2=2.3456\nG90 G0 X[ROUND[#1]+ROUND[#2]] Z1.\nM30\n");
    require_clean(r);
    const auto x = x_at(r, 1);
    REQUIRE(x);
    CHECK(*x == Approx(3.581).margin(1e-9));
}

// --- vacant (#0) ---------------------------------------------------------------------------------

// FANUC "Undefined variables": replacement keeps vacancy (#1=#0 → vacant, #2=#1 → vacant); in
// arithmetic a vacant value is 0: #0+1 = 1, #0*5 = 0, #0−3 = −3, #1+#1 = 0, SIN[#0] = 0.
TEST_CASE("#0 in assignments and arithmetic", "[macro]") {
    const auto got = values("#1=#0\n#2=#1\n", {"#0", "#1", "#2", "#0+1", "#0*5", "#0-3", "#1+#1", "SIN[#0]"});
    CHECK_FALSE(got[0].has_value());
    CHECK_FALSE(got[1].has_value());
    CHECK_FALSE(got[2].has_value());
    REQUIRE(got[3]);
    CHECK(*got[3] == 1);
    REQUIRE(got[4]);
    CHECK(*got[4] == 0);
    REQUIRE(got[5]);
    CHECK(*got[5] == -3);
    REQUIRE(got[6]);
    CHECK(*got[6] == 0);
    REQUIRE(got[7]);
    CHECK(*got[7] == 0);
}

// The FANUC table ("conditional expressions" with #1 vacant / #1 = 0):
//              #1 EQ #0   #1 NE 0   #1 GE #0   #1 GT 0
//   vacant     true       true      true       false
//   0          false      false     true       false
// and with #0 itself: #0 EQ #0 true, 0 EQ #0 false, #0 NE 0 true; GE/LE/GT/LT take it as 0:
// #0 GE 0 true, #0 LE 0 true, #0 GT 0 false, #0 LT 0 false.
TEST_CASE("#0 in comparisons (the FANUC table)", "[macro]") {
    const std::vector<std::string> vacant_rows = {"#1 EQ #0", "#1 NE 0", "#1 GE #0", "#1 GT 0"};
    const auto vacant = conditions("", vacant_rows);
    CHECK(vacant[0]);
    CHECK(vacant[1]);
    CHECK(vacant[2]);
    CHECK_FALSE(vacant[3]);
    const auto zero = conditions("#1=0\n", vacant_rows);
    CHECK_FALSE(zero[0]);
    CHECK_FALSE(zero[1]);
    CHECK(zero[2]);
    CHECK_FALSE(zero[3]);
    const auto own = conditions("", {"#0 EQ #0", "0 EQ #0", "#0 NE 0", "#0 GE 0", "#0 LE 0", "#0 GT 0", "#0 LT 0"});
    CHECK(own[0]);
    CHECK_FALSE(own[1]);
    CHECK(own[2]);
    CHECK(own[3]);
    CHECK(own[4]);
    CHECK_FALSE(own[5]);
    CHECK_FALSE(own[6]);
}

// FANUC: "G90 X100 Y#1" with #1 vacant is "G90 X100": the move happens without Y (Y stays 7);
// a block whose only axis word is vacant does not move at all (two moves in total).
TEST_CASE("a vacant variable omits its address", "[macro]") {
    const Run r = run_bare("O1\nG90 G0 X0. Y7.\nG0 X100. Y#5\nG0 Y#5\nM30\n");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].end[X] == Approx(100));
    CHECK(m[1].end[Y] == Approx(7));
}

// --- alarms ------------------------------------------------------------------------------------------

// Each program stops at its alarm (FANUC numbers, 16i list): 112 division by zero (also in an
// address), 115 illegal variable number (#34 does not exist), 116 write to #0, 119 argument
// (SQRT of a negative), 118 six bracket levels, 114 a comparison used as a value. The move after
// the alarm never happens.
TEST_CASE("macro alarms stop the program", "[macro]") {
    const std::vector<std::pair<std::string, int>> cases = {
        {"#1=1/0", 112},  {"G0 X[1/0]", 112}, {"#1=#2/[#3-#3]", 112}, {"#34=1", 115},
        {"#0=1", 116},    {"#1=SQRT[-1]", 119}, {"#1=[[[[[[1]]]]]]", 118}, {"#2=[1 LT 2]", 114},
    };
    for (const auto& [statement, number] : cases) {
        INFO(statement);
        const Run r = run_bare("O1\nG90 G0 X0. Y0.\n" + statement + "\nG0 X5.\nM30\n");
        require_alarm(r, number);
        CHECK(moves(r).size() == 1);
    }
}

// --- G65 arguments (argument specification I) --------------------------------------------------------

// A→#1 B→#2 C→#3 I→#4 J→#5 K→#6 D→#7 E→#8 F→#9 H→#11 M→#13 Q→#17 R→#18 S→#19 T→#20 U→#21 V→#22
// W→#23 X→#24 Y→#25 Z→#26; G L N O P are not arguments, so #10 #12 #14 #15 #16 stay vacant.
// The call passes the value n for the letter of #n; O9000 shows #n (or −1 when vacant) as the X of
// a move tagged Z = n, for n = 1..26.
TEST_CASE("G65 argument specification I maps every letter to its local", "[macro]") {
    std::string text = "O1\nG90 G0 X0. Y0. Z0.\n"
                       "G65 P9000 A1. B2. C3. I4. J5. K6. D7. E8. F9. H11. M13. Q17. R18. S19. T20. U21. V22. W23. "
                       "X24. Y25. Z26.\nM30\nO9000\n";
    for (int n = 1; n <= 26; ++n)
        text += "#100=-1\nIF [#" + std::to_string(n) + " NE #0] THEN #100=#" + std::to_string(n) + "\nG0 X#100 Z" +
                std::to_string(n) + ".\n";
    text += "M99\n";
    const Run r = run_bare(text);
    require_clean(r);
    for (int n = 1; n <= 26; ++n) {
        INFO("#" << n);
        const auto x = x_at(r, n);
        REQUIRE(x);
        const bool vacant = n == 10 || n == 12 || n == 14 || n == 15 || n == 16;
        CHECK(*x == Approx(vacant ? -1.0 : static_cast<double>(n)));
    }
}

// [FANUC] "The units used for argument data passed without a decimal point correspond to the least
// input increment of each address": fanuc-mill IS-B metric, G65 X10 → #24 = 0.010; ADP[#24]
// (30i "add a decimal point") gives 10. With a point, X10. → #24 = 10.
//   O9300 shows #24·1000 at Z1 (10 for 0.010) and ADP[#24] at Z2 (10); the second call, with X10.,
//   shows #24 at Z3 (10).
TEST_CASE("G65 arguments without a decimal point are in least input increments", "[macro]") {
    const Run r = run_bare("O1\nG90 G0 X0. Y0. Z0.\nG65 P9300 X10\nG65 P9301 X10.\nM30\n"
                           "O9300\nG0 X[#24*1000] Z1.\n#1=ADP[#24]\nG0 X#1 Z2.\nM99\n"
                           "O9301\nG0 X#24 Z3.\nM99\n");
    require_clean(r);
    REQUIRE(x_at(r, 1));
    CHECK(*x_at(r, 1) == Approx(10));
    REQUIRE(x_at(r, 2));
    CHECK(*x_at(r, 2) == Approx(10));
    REQUIRE(x_at(r, 3));
    CHECK(*x_at(r, 3) == Approx(10));
}

// Locals are per call level; commons are shared (FANUC "Types of variables"):
//   main: #1 = 5, G65 P9100 A7.
//   O9100 (level 1): #1 = 7 (the argument) → Z3 shows 7; sets #2 = 8; G65 P9101
//   O9101 (level 2): #1 vacant → Z7 shows −1; sets #1 = 99 and #100 = 99
//   back in O9100: #1 = 7 (Z4), #2 = 8 (Z5), #100 = 99 (Z6)
//   back in main: #1 = 5 (Z1), #2 vacant → −1 (Z2)
TEST_CASE("G65: local variables per call level, commons shared", "[macro]") {
    const Run r = run_bare("O1\n#1=5.\n#100=0\nG90 G0 X0. Y0. Z0.\nG65 P9100 A7.\nG0 X#1 Z1.\n"
                           "#101=-1\nIF [#2 NE #0] THEN #101=#2\nG0 X#101 Z2.\nM30\n"
                           "O9100\nG0 X#1 Z3.\n#2=8.\nG65 P9101\nG0 X#1 Z4.\nG0 X#2 Z5.\nG0 X#100 Z6.\nM99\n"
                           "O9101\n#199=-1\nIF [#1 NE #0] THEN #199=#1\nG0 X#199 Z7.\n#1=99.\n#100=99.\nM99\n");
    require_clean(r);
    const std::vector<std::pair<double, double>> expected = {{1, 5}, {2, -1}, {3, 7}, {4, 7}, {5, 8}, {6, 99}, {7, -1}};
    for (const auto& [tag, value] : expected) {
        INFO("Z" << tag);
        const auto x = x_at(r, tag);
        REQUIRE(x);
        CHECK(*x == Approx(value));
    }
}

// M98 does not open a level: the subprogram works on the caller's #1 (5 + 1 = 6).
TEST_CASE("M98 subprograms share the caller's locals", "[macro]") {
    const Run r = run_bare("O1\n#1=5.\nG90 G0 X0. Y0. Z0.\nM98 P9200\nG0 X#1 Z1.\nM30\nO9200\n#1=#1+1.\nM99\n");
    require_clean(r);
    REQUIRE(x_at(r, 1));
    CHECK(*x_at(r, 1) == Approx(6));
}

// --- WHILE / DO / END --------------------------------------------------------------------------------

// Three nested loops of 2, 3 and 4 passes: #100 counts 2·3·4 = 24 inner passes.
TEST_CASE("WHILE loops nest three deep", "[macro]") {
    const Run r = run_bare("O1\n#100=0\n#1=0\nWHILE [#1 LT 2] DO 1\n#2=0\nWHILE [#2 LT 3] DO 2\n#3=0\n"
                           "WHILE [#3 LT 4] DO 3\n#100=#100+1\n#3=#3+1\nEND 3\n#2=#2+1\nEND 2\n#1=#1+1\nEND 1\n"
                           "G90 G0 X#100 Z1.\nM30\n");
    require_clean(r);
    REQUIRE(x_at(r, 1));
    CHECK(*x_at(r, 1) == Approx(24));
}

// A fourth nested level (it must reuse an identifier, here DO 1 inside DO 3) is an alarm: "DO loops
// can be nested to a maximum depth of three levels". The 16i manual does not name the number for
// this case; 124 (DO/END do not correspond) or 126 (illegal loop number) are the candidates.
TEST_CASE("a fourth WHILE level is an alarm", "[macro]") {
    const Run r = run_bare("O1\nWHILE [#1 LT 1] DO 1\nWHILE [#2 LT 1] DO 2\nWHILE [#3 LT 1] DO 3\nWHILE [#4 LT 1] DO 1\n"
                           "#4=1\nEND 1\n#3=1\nEND 3\n#2=1\nEND 2\n#1=1\nEND 1\nM30\n");
    INFO(alarm_list(r));
    REQUIRE(r.result.alarms.size() == 1);
    CHECK((r.result.alarms[0].code == 124 || r.result.alarms[0].code == 126));
    CHECK_FALSE(r.result.completed);
}

// FANUC alarm 126 "illegal loop number: in DO n, 1 ≤ n ≤ 3 is not established".
TEST_CASE("DO 4 is alarm 126", "[macro]") {
    const Run r = run_bare("O1\n#1=0\nWHILE [#1 LT 1] DO 4\n#1=1\nEND 4\nM30\n");
    require_alarm(r, 126);
}

// FANUC alarm 124 "DO and END do not correspond": END 2 closing DO 1; a DO whose END is missing
// (the false condition looks for END 1); an END without any DO.
TEST_CASE("DO/END mismatches are alarm 124", "[macro]") {
    require_alarm(run_bare("O1\n#1=0\nWHILE [#1 LT 2] DO 1\n#1=#1+1\nEND 2\nM30\n"), 124);
    require_alarm(run_bare("O1\nWHILE [1 EQ 2] DO 1\nG0 X1.\nM30\n"), 124);
    require_alarm(run_bare("O1\nG0 X1.\nEND 1\nM30\n"), 124);
}

// --- GOTO and IF ---------------------------------------------------------------------------------------

// Computed GOTO: #1 = 20 → GOTO #1 goes to N20 (X20), skipping X99; GOTO [#2·3] with #2 = 10 → N30
// (Y30), skipping X98; IF [#1 EQ 20] GOTO 40 jumps (Z40), skipping X97; IF [#1 NE 20] GOTO 50 does
// not, so Z41 runs. Moves: start, X20, Y30, Z40, Z41.
TEST_CASE("computed GOTO and IF GOTO", "[macro]") {
    const Run r = run_bare("O1\nG90 G0 X0. Y0. Z0.\n#1=20\nGOTO #1\nG0 X99.\nN20 G0 X20.\n#2=10\nGOTO [#2*3]\nG0 X98.\n"
                           "N30 G0 Y30.\nIF [#1 EQ 20] GOTO 40\nG0 X97.\nN40 G0 Z40.\nIF [#1 NE 20] GOTO 50\nG0 Z41.\n"
                           "N50 M30\n");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 5);
    CHECK(m[1].end[X] == Approx(20));
    CHECK(m[2].end[Y] == Approx(30));
    CHECK(m[3].end[Z] == Approx(40));
    CHECK(m[4].end[Z] == Approx(41));
    for (const Event& e : m) CHECK(e.end[X] < 90);
}

// GOTO to a sequence number the program lacks stops with an alarm (16i list: 128 "the sequence
// number specified in the branch command ... cannot be searched").
TEST_CASE("GOTO to a missing sequence number is an alarm", "[macro]") {
    require_alarm(run_bare("O1\nGOTO 77\nM30\n"), 128);
}

// IF [..] THEN runs its statement only when the condition holds: #2 = 5 (taken), #3 stays 0.
TEST_CASE("IF THEN", "[macro]") {
    const auto got = values("#1=1\n#2=0\n#3=0\nIF [#1 EQ 1] THEN #2=5\nIF [#1 EQ 2] THEN #3=5\n", {"#2", "#3"});
    REQUIRE(got[0]);
    CHECK(*got[0] == 5);
    REQUIRE(got[1]);
    CHECK(*got[1] == 0);
}

// --- the step limit ------------------------------------------------------------------------------------

// Endless loops end at Setup::step_limit with an alarm: `N10 GOTO 10` and an always-true WHILE.
// Limit 50: the 51st block raises it (blocks ≤ 51).
TEST_CASE("endless macro loops end at the step limit", "[macro]") {
    for (const char* text : {"O1\nN10 GOTO 10\nM30\n", "O1\nWHILE [1 EQ 1] DO 1\nEND 1\nM30\n"}) {
        INFO(text);
        const Run r = run_bare(text, "fanuc-mill", [](Setup& s) { s.step_limit = 50; });
        REQUIRE(r.result.alarms.size() == 1);
        CHECK(r.result.alarms[0].text.find("step limit") != std::string::npos);
        CHECK(r.result.blocks <= 51);
        CHECK_FALSE(r.result.completed);
    }
}
