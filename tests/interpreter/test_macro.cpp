// Custom Macro B evaluator (interpreter/macro): every operator and function, FANUC's vacant rules,
// variable storage and levels, and the alarms (111 overflow, 112 division by zero, 114 format,
// 115 variable number, 116 write-protected, 118 nesting, 119 argument). Expressions are parsed
// from real program text with the fanuc-mill dialect.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

#include "ast/dump.hpp"
#include "grammar/parse.hpp"
#include "interpreter/macro/evaluate.hpp"

using namespace kerf;
using namespace kerf::interpreter::macro;
using Catch::Matchers::Contains;

namespace {

ast::SyntaxTree parse(const std::string& text) {
    const dialects::Dialect* d = dialects::builtin_registry().find("fanuc-mill");
    REQUIRE(d != nullptr);
    ast::SyntaxTree tree = grammar::parse(text, d->lexical);
    INFO(text);
    REQUIRE(tree.diagnostics.empty());
    return tree;
}

// The top-level statements of a program, in order.
std::vector<const ast::Statement*> statements(const ast::SyntaxTree& tree) {
    std::vector<const ast::Statement*> out;
    for (const ast::Token& t : tree.tokens)
        if (t.kind == ast::TokenKind::statement) out.push_back(&tree.statements[static_cast<std::size_t>(t.payload)]);
    return out;
}

// Runs every assignment of `program`; returns the first error.
std::optional<Error> run(const std::string& program, Variables& vars, const Options& options = {}) {
    const ast::SyntaxTree tree = parse(program);
    for (const ast::Statement* s : statements(tree)) {
        REQUIRE(s->kind == ast::StatementKind::assign);
        if (auto e = assign(tree, *s, vars, options)) return e;
    }
    return std::nullopt;
}

struct Evaluated {
    ast::SyntaxTree tree;
    Result result;
    std::string error_text() const {
        return result.error ? std::string(tree.slice(result.error->range)) : std::string();
    }
};

// Evaluates `expression` as the right side of "#999=<expression>".
Evaluated eval(const std::string& expression, Variables& vars, const Options& options = {}) {
    Evaluated e{parse("#999=" + expression + "\n"), {}};
    const auto st = statements(e.tree);
    REQUIRE(st.size() == 1);
    e.result = evaluate(e.tree, st[0]->value, vars, options);
    return e;
}

Evaluated eval(const std::string& expression, const Options& options = {}) {
    Variables vars;
    return eval(expression, vars, options);
}

// The number `expression` evaluates to; fails the test on an error or a vacant result.
double number(const std::string& expression, Variables& vars, const Options& options = {}) {
    const Evaluated e = eval(expression, vars, options);
    INFO(expression << " -> " << (e.result.error ? e.result.error->message : std::string()));
    REQUIRE(e.result.ok());
    REQUIRE_FALSE(e.result.value.vacant);
    return e.result.value.number;
}

double number(const std::string& expression, const Options& options = {}) {
    Variables vars;
    return number(expression, vars, options);
}

// The FANUC alarm `expression` raises (0 = none).
int alarm(const std::string& expression, Variables& vars, const Options& options = {}) {
    const Evaluated e = eval(expression, vars, options);
    return e.result.error ? e.result.error->alarm : 0;
}

int alarm(const std::string& expression, const Options& options = {}) {
    Variables vars;
    return alarm(expression, vars, options);
}

struct Condition {
    ast::SyntaxTree tree;
    ConditionResult result;
};

// Evaluates the condition of "IF [<text>] GOTO 1".
Condition condition(const std::string& text, Variables& vars, const Options& options = {}) {
    Condition c{parse("IF [" + text + "] GOTO 1\n"), {}};
    const auto st = statements(c.tree);
    REQUIRE(st.size() == 1);
    REQUIRE(st[0]->kind == ast::StatementKind::if_goto);
    c.result = evaluate_condition(c.tree, st[0]->value, vars, options);
    return c;
}

bool holds(const std::string& text, Variables& vars, const Options& options = {}) {
    const Condition c = condition(text, vars, options);
    INFO(text << " -> " << (c.result.error ? c.result.error->message : std::string()));
    REQUIRE(c.result.ok());
    REQUIRE(c.result.value.has_value());
    return *c.result.value;
}

bool holds(const std::string& text) {
    Variables vars;
    return holds(text, vars);
}

Value read(Variables& vars, int n) {
    const auto v = vars.read(n);
    REQUIRE(v.has_value());
    return *v;
}

// A system-variable implementation for the tests: a map, #3000-#3999 writable, #4001+ read-only,
// #3000 accepts 0..200 only (like the alarm number), the hook can protect any number.
struct TestSystem : SystemVariables {
    std::map<int, Value> values{{4001, Value::of(1)}, {5001, Value::of(12.5)}, {3001, Value::of(0)}};
    std::vector<int> protected_numbers;
    std::optional<Value> read(int n) override {
        const auto it = values.find(n);
        if (it == values.end()) return std::nullopt;
        return it->second;
    }
    WriteResult write(int n, Value v) override {
        if (n >= 4001) return values.count(n) ? WriteResult::read_only : WriteResult::undefined;
        if (n < 3000 || n > 3999) return WriteResult::undefined;
        if (n == 3000 && (v.vacant || v.number < 0 || v.number > 200)) return WriteResult::invalid_value;
        values[n] = v;
        return WriteResult::ok;
    }
    bool read_only(int n) const override {
        for (int p : protected_numbers)
            if (p == n) return true;
        return n >= 4001 && values.count(n) != 0;
    }
};

}  // namespace

// --- values ---------------------------------------------------------------------------------------

TEST_CASE("Value: vacant, numbers, equality, rounding helpers") {
    CHECK(Value::vacant_value().vacant);
    CHECK(is_vacant(Value{}));
    CHECK_FALSE(Value::of(0).vacant);
    CHECK(Value::of(0) != Value::vacant_value());
    CHECK(Value::of(2.5) == Value::of(2.5));
    CHECK(Value{true, 3.0} == Value::vacant_value());
    CHECK(Value::vacant_value().or_zero() == 0.0);
    CHECK(round_half_away(1.5) == 2.0);
    CHECK(round_half_away(-1.5) == -2.0);
    CHECK(round_half_away(1.4999) == 1.0);
    CHECK(round_to_integer(2.5, 0, 10) == 3);
    CHECK_FALSE(round_to_integer(-0.6, 0, 10).has_value());
    CHECK_FALSE(round_to_integer(NAN, 0, 10).has_value());
}

// --- variables ------------------------------------------------------------------------------------

TEST_CASE("Variables: #0, locals, commons, undefined numbers") {
    Variables vars;
    CHECK(read(vars, 0).vacant);
    CHECK(vars.read_only(0));
    CHECK(vars.write(0, Value::of(1)) == WriteResult::read_only);
    CHECK(read(vars, 0).vacant);
    for (int n : {1, 17, 33, 100, 199, 500, 999}) {
        INFO(n);
        CHECK(read(vars, n).vacant);   // everything starts vacant
        CHECK(vars.write(n, Value::of(n)) == WriteResult::ok);
        CHECK(read(vars, n) == Value::of(n));
    }
    for (int n : {-1, 34, 99, 200, 499, 1000, 3000, 5001}) {
        INFO(n);
        CHECK_FALSE(vars.read(n).has_value());
        CHECK(vars.write(n, Value::of(1)) == WriteResult::undefined);
    }
    CHECK(vars.write(1, Value::vacant_value()) == WriteResult::ok);
    CHECK(read(vars, 1).vacant);
}

TEST_CASE("Variables: local levels for G65/G66 calls") {
    Variables vars;
    CHECK(vars.level() == 0);
    vars.write(1, Value::of(10));
    vars.write(33, Value::of(33));
    vars.write(100, Value::of(100));
    vars.write(500, Value::of(500));
    vars.push_level();
    CHECK(vars.level() == 1);
    CHECK(read(vars, 1).vacant);   // a new level's locals start vacant
    CHECK(read(vars, 33).vacant);
    CHECK(read(vars, 100) == Value::of(100));   // commons are shared by all levels
    CHECK(read(vars, 500) == Value::of(500));
    vars.write(1, Value::of(20));
    vars.write(101, Value::of(101));
    vars.push_level();
    CHECK(vars.level() == 2);
    CHECK(read(vars, 1).vacant);
    CHECK(vars.pop_level());
    CHECK(read(vars, 1) == Value::of(20));
    CHECK(vars.pop_level());
    CHECK(vars.level() == 0);
    CHECK(read(vars, 1) == Value::of(10));   // the caller's locals come back
    CHECK(read(vars, 101) == Value::of(101));
    CHECK_FALSE(vars.pop_level());   // nothing to return to
    CHECK(vars.level() == 0);
}

TEST_CASE("Variables: reset clears locals and #100-#199, keeps #500-#999") {
    Variables vars;
    vars.write(1, Value::of(1));
    vars.write(150, Value::of(150));
    vars.write(777, Value::of(777));
    vars.push_level();
    vars.write(2, Value::of(2));
    vars.reset();
    CHECK(vars.level() == 0);
    CHECK(read(vars, 1).vacant);
    CHECK(read(vars, 2).vacant);
    CHECK(read(vars, 150).vacant);
    CHECK(read(vars, 777) == Value::of(777));

    SECTION("parameter 6001#6 CCV = 1 keeps #100-#199 at reset, not at power-off") {
        vars.keep_commons_on_reset = true;
        vars.write(150, Value::of(150));
        vars.reset();
        CHECK(read(vars, 150) == Value::of(150));
        vars.power_cycle();
        CHECK(read(vars, 150).vacant);
        CHECK(read(vars, 777) == Value::of(777));
    }
}

TEST_CASE("Variables: system variables are delegated, with a read-only hook") {
    TestSystem system;
    Variables vars(system);
    CHECK(read(vars, 4001) == Value::of(1));
    CHECK(read(vars, 5001) == Value::of(12.5));
    CHECK_FALSE(vars.read(1234).has_value());
    CHECK(vars.write(3003, Value::of(1)) == WriteResult::ok);
    CHECK(system.values[3003] == Value::of(1));
    CHECK(vars.write(4001, Value::of(2)) == WriteResult::read_only);
    CHECK(vars.write(3000, Value::of(500)) == WriteResult::invalid_value);
    system.protected_numbers = {500};   // parameters 6031/6032 style protection of a common
    CHECK(vars.write(500, Value::of(1)) == WriteResult::read_only);
    CHECK(vars.write(501, Value::of(1)) == WriteResult::ok);
    CHECK(&vars.system() == &system);
}

// The interpreter evaluates a block read ahead with the live variables and the system variables of
// the machine state it reads with (interpreter/executor.hpp, look_ahead): an expression takes the
// variables const, so it cannot change one (this test would not compile otherwise), and #1000 and up
// come from the hook it is given, not from the variables' own; an assignment writes #1000 and up
// through the hook it is given.
TEST_CASE("Variables: an expression reads them const, with the system hook it is given") {
    TestSystem own, ahead;
    ahead.values[5001] = Value::of(40);
    Variables vars(own);
    REQUIRE(vars.write(100, Value::of(2)) == WriteResult::ok);
    const Variables& read_only = vars;
    const ast::SyntaxTree tree = parse("#999=#100*#5001\n");
    const auto st = statements(tree);
    REQUIRE(st.size() == 1);
    const Result with_own = evaluate(tree, st[0]->value, read_only);
    REQUIRE(with_own.ok());
    CHECK(with_own.value == Value::of(25));   // 2 × 12.5
    const Result with_ahead = evaluate(tree, st[0]->value, read_only, ahead);
    REQUIRE(with_ahead.ok());
    CHECK(with_ahead.value == Value::of(80));   // 2 × 40
    const ast::SyntaxTree set = parse("#3003=7\n");
    REQUIRE_FALSE(assign(set, *statements(set).at(0), vars, ahead).has_value());
    CHECK(ahead.values[3003] == Value::of(7));
    CHECK(own.values.count(3003) == 0);
}

// --- arithmetic -----------------------------------------------------------------------------------

TEST_CASE("arithmetic: + - * / with FANUC precedence") {
    CHECK(number("1+2") == 3);
    CHECK(number("5-7") == -2);
    CHECK(number("2*3.5") == 7);
    CHECK(number("7/2") == 3.5);
    CHECK(number("1+2*3") == 7);
    CHECK(number("[1+2]*3") == 9);
    CHECK(number("10-4-3") == 3);   // left to right
    CHECK(number("12/3/2") == 2);
    CHECK(number("-3+5") == 2);
    CHECK(number("+3") == 3);
    CHECK(number("-[2*3]") == -6);
    CHECK(number("--2") == 2);
    CHECK(number("1.5") == 1.5);
    CHECK(number("-.5") == -0.5);
    CHECK(number("1/3") == 1.0 / 3.0);   // no intermediate rounding to 8 digits
    CHECK(number("0.1+0.2") == 0.1 + 0.2);
    CHECK_FALSE(std::signbit(number("-0")));   // no negative zero
    CHECK_FALSE(std::signbit(number("0*-1")));
}

TEST_CASE("arithmetic: division by zero is alarm 112 on the division") {
    Variables vars;
    vars.write(2, Value::of(0));
    const Evaluated e = eval("1+#1/#2", vars);
    REQUIRE(e.result.error);
    CHECK(e.result.error->alarm == 112);
    CHECK(e.result.error->code == "M0112");
    CHECK(e.error_text() == "#1/#2");
    CHECK_THAT(e.result.error->message, Contains("#1/#2"));
    CHECK(e.result.value.vacant);
    CHECK(alarm("1/0") == 112);
    CHECK(alarm("1/#0") == 112);   // a vacant divisor is 0
    CHECK(alarm("0/0") == 112);
    CHECK(alarm("1/[0.5-0.5]") == 112);
}

TEST_CASE("arithmetic: results out of range are alarm 111") {
    CHECK(alarm("1000000000000000000000000*1000000000000000000000000") == 111);
    CHECK(alarm("EXP[108]") == 0);     // 8.0e46
    CHECK(alarm("EXP[110]") == 111);   // 5.9e47: the manual's "about 110" limit
    Options o30i;
    o30i.max_magnitude = 1e308;
    CHECK(alarm("EXP[200]", o30i) == 0);
    CHECK(alarm("EXP[200]") == 111);
    CHECK(alarm("EXP[1000]", o30i) == 111);   // infinite
}

// --- vacant --------------------------------------------------------------------------------------

TEST_CASE("vacant: replacement keeps it, other operations take it as 0") {
    Variables vars;
    vars.write(1, Value::of(5));
    REQUIRE_FALSE(run("#1=#0\n", vars));
    CHECK(read(vars, 1).vacant);   // #1=#0: a plain copy stays vacant
    vars.write(3, Value::of(9));
    REQUIRE_FALSE(run("#3=#2\n", vars));   // #2 never set
    CHECK(read(vars, 3).vacant);
    REQUIRE_FALSE(run("#4=#0+0\n#5=#0*5\n#6=#1+#1\n#7=#1-3\n#8=SIN[#1]\n#9=ABS[#1]\n", vars));
    CHECK(read(vars, 4) == Value::of(0));
    CHECK(read(vars, 5) == Value::of(0));
    CHECK(read(vars, 6) == Value::of(0));
    CHECK(read(vars, 7) == Value::of(-3));
    CHECK(read(vars, 8) == Value::of(0));
    CHECK(read(vars, 9) == Value::of(0));
    REQUIRE_FALSE(run("#10=[#0]\n#11=+#0\n#12=-#0\n#13=[[#1]]\n", vars));
    CHECK(read(vars, 10).vacant);   // brackets only group
    CHECK(read(vars, 11).vacant);
    CHECK(read(vars, 12).vacant);   // a signed quotation of a vacant variable stays vacant
    CHECK(read(vars, 13).vacant);
    // As an address value, vacant means "omit the address" (G90 X100 Y#1 -> G90 X100).
    CHECK(is_vacant(eval("#1", vars).result.value));
    CHECK(is_vacant(eval("-#1", vars).result.value));
    CHECK_FALSE(is_vacant(eval("#1+10", vars).result.value));
    CHECK(number("#1+10", vars) == 10);
}

TEST_CASE("vacant: EQ/NE distinguish it from 0, GT/LT/GE/LE take it as 0 (manual table)") {
    Variables vars;
    // #101 vacant
    CHECK(holds("#101 EQ #0", vars));
    CHECK(holds("#101 NE 0", vars));
    CHECK(holds("#101 GE #0", vars));
    CHECK_FALSE(holds("#101 GT 0", vars));
    CHECK(holds("#101 LE #0", vars));
    CHECK_FALSE(holds("#101 LT 0", vars));
    CHECK_FALSE(holds("#101 EQ 0", vars));
    CHECK_FALSE(holds("#101 NE #0", vars));
    CHECK(holds("#0 EQ #0", vars));
    CHECK(holds("#101 GE 0", vars));
    CHECK(holds("#101 LE 0", vars));
    CHECK_FALSE(holds("#101 EQ [#0+0]", vars));   // [#0+0] is 0, not vacant
    // #101 = 0
    vars.write(101, Value::of(0));
    CHECK_FALSE(holds("#101 EQ #0", vars));
    CHECK_FALSE(holds("#101 NE 0", vars));
    CHECK(holds("#101 GE #0", vars));
    CHECK_FALSE(holds("#101 GT 0", vars));
    CHECK(holds("#101 LE #0", vars));
    CHECK_FALSE(holds("#101 LT 0", vars));
    CHECK(holds("#101 EQ 0", vars));
    CHECK(holds("#101 NE #0", vars));
}

// --- comparisons and conditions -----------------------------------------------------------------

TEST_CASE("conditions: every comparison operator") {
    CHECK(holds("1 EQ 1"));
    CHECK_FALSE(holds("1 EQ 2"));
    CHECK(holds("1 NE 2"));
    CHECK_FALSE(holds("2 NE 2"));
    CHECK(holds("3 GT 2"));
    CHECK_FALSE(holds("2 GT 2"));
    CHECK(holds("1 LT 2"));
    CHECK_FALSE(holds("2 LT 2"));
    CHECK(holds("2 GE 2"));
    CHECK_FALSE(holds("1 GE 2"));
    CHECK(holds("2 LE 2"));
    CHECK_FALSE(holds("3 LE 2"));
    CHECK(holds("1+1 EQ 2"));   // comparisons bind loosest
    CHECK(holds("[1+1] eq [4/2]"));   // keywords in lower case
    CHECK(holds("-1 LT 0"));
}

TEST_CASE("conditions: AND/OR/XOR of bracketed conditions (30i)") {
    Variables vars;
    vars.write(1, Value::of(1));
    vars.write(2, Value::of(5));
    CHECK(holds("[#1 EQ 1] AND [#2 GT 0]", vars));
    CHECK_FALSE(holds("[#1 EQ 2] AND [#2 GT 0]", vars));
    CHECK(holds("[#1 EQ 2] OR [#2 GT 0]", vars));
    CHECK_FALSE(holds("[#1 EQ 2] OR [#2 LT 0]", vars));
    CHECK(holds("[#1 EQ 1] XOR [#2 LT 0]", vars));
    CHECK_FALSE(holds("[#1 EQ 1] XOR [#2 GT 0]", vars));
    CHECK(holds("[[#1 EQ 1] AND [#2 GT 0]] OR [#1 EQ 7]", vars));
    Options strict;
    strict.logical_conditions = false;
    const Condition c = condition("[#1 EQ 1] AND [#2 GT 0]", vars, strict);
    REQUIRE(c.result.error);
    CHECK(c.result.error->alarm == 114);
}

TEST_CASE("conditions: a value is not a condition, a condition is not a value (alarm 114)") {
    Variables vars;
    const Condition c = condition("#1", vars);
    REQUIRE(c.result.error);
    CHECK(c.result.error->alarm == 114);
    CHECK(c.result.error->code == "M0114");
    CHECK_FALSE(c.result.value.has_value());
    CHECK(condition("1+2", vars).result.error->alarm == 114);
    CHECK(condition("[1 EQ 1] + 1 GT 0", vars).result.error->alarm == 114);
    const Evaluated e = eval("[1 LT 2]", vars);   // "#2=[1 LT 2]" is illegal
    REQUIRE(e.result.error);
    CHECK(e.result.error->alarm == 114);
    CHECK(e.error_text() == "1 LT 2");
}

TEST_CASE("conditions: errors inside a comparison are reported") {
    Variables vars;
    const Condition c = condition("1/0 GT 0", vars);
    REQUIRE(c.result.error);
    CHECK(c.result.error->alarm == 112);
    CHECK(condition("#34 EQ 0", vars).result.error->alarm == 115);
}

// --- logical and MOD -------------------------------------------------------------------------------

TEST_CASE("AND, OR, XOR work bit by bit on integers") {
    CHECK(number("5 AND 3") == 1);
    CHECK(number("5 OR 3") == 7);
    CHECK(number("5 XOR 3") == 6);
    CHECK(number("12 AND 10") == 8);
    CHECK(number("255 AND 4294967295") == 255);
    CHECK(number("-1 AND 255") == 255);   // two's complement
    CHECK(number("1 OR 2 AND 3") == 3);   // AND is multiplicative: 1 OR [2 AND 3]
    CHECK(number("#0 OR 4") == 4);        // vacant as 0
    CHECK(number("[0.1*30] AND 7") == 3);   // 3.0000000000000004 is an integer within 1e-9
    CHECK(alarm("1.5 AND 1") == 119);
    CHECK(alarm("1 OR 2.5") == 119);
    CHECK(alarm("4294967296 XOR 1") == 119);
}

TEST_CASE("MOD: remainder of the rounded operands, sign of the dividend") {
    CHECK(number("10 MOD 3") == 1);
    CHECK(number("27 MOD 20") == 7);
    CHECK(number("-10 MOD 3") == -1);
    CHECK(number("10 MOD -3") == 1);
    CHECK(number("9 MOD 3") == 0);
    CHECK(number("10.4 MOD 3") == 1);
    CHECK(number("10.5 MOD 3") == 2);   // 11 MOD 3
    CHECK(number("2+10 MOD 3") == 3);   // MOD is multiplicative
    CHECK(alarm("10 MOD 0") == 112);
    CHECK(alarm("10 MOD 0.4") == 112);
    CHECK(alarm("10 MOD #0") == 112);
}

// --- functions --------------------------------------------------------------------------------------

TEST_CASE("SIN, COS, TAN in degrees") {
    CHECK(number("SIN[30]") == 0.5);
    CHECK(number("SIN[90]") == 1);
    CHECK(number("SIN[180]") == 0);
    CHECK(number("SIN[270]") == -1);
    CHECK(number("SIN[-30]") == -0.5);
    CHECK(number("SIN[390]") == 0.5);
    CHECK(number("SIN[150]") == 0.5);
    CHECK(number("SIN[45]") == Approx(std::sqrt(0.5)));
    CHECK(number("SIN[10]") == Approx(std::sin(10 * M_PI / 180)));
    CHECK(number("SIN[90.5]") == Approx(std::sin(90.5 * M_PI / 180)));   // 90 degrees 30 minutes
    CHECK(number("COS[0]") == 1);
    CHECK(number("COS[60]") == 0.5);
    CHECK(number("COS[90]") == 0);
    CHECK_FALSE(std::signbit(number("COS[90]")));
    CHECK(number("COS[180]") == -1);
    CHECK(number("COS[-60]") == 0.5);
    CHECK(number("COS[33]") == Approx(std::cos(33 * M_PI / 180)));
    CHECK(number("TAN[45]") == 1);
    CHECK(number("TAN[-45]") == -1);
    CHECK(number("TAN[135]") == -1);
    CHECK(number("TAN[0]") == 0);
    CHECK(number("TAN[180]") == 0);
    CHECK(number("TAN[30]") == Approx(1 / std::sqrt(3.0)));
    CHECK(number("TAN[100]") == Approx(std::tan(100 * M_PI / 180)));
    CHECK(number("TAN[-100]") == Approx(std::tan(-100 * M_PI / 180)));
    CHECK(alarm("TAN[90]") == 112);   // alarm 112 includes tan 90
    CHECK(alarm("TAN[-270]") == 112);
}

TEST_CASE("ASIN and ACOS: solution ranges and domain (alarm 119)") {
    CHECK(number("ASIN[0.5]") == 30);
    CHECK(number("ASIN[1]") == 90);
    CHECK(number("ASIN[0]") == 0);
    CHECK(number("ASIN[-0.5]") == 330);   // NAT = 0: 270..90 through 0
    CHECK(number("ASIN[-1]") == 270);
    Options nat1;
    nat1.angle_range = AngleRange::minus_180_to_180;
    CHECK(number("ASIN[-0.5]", nat1) == -30);
    CHECK(number("ASIN[-1]", nat1) == -90);
    CHECK(number("ASIN[0.3]") == Approx(std::asin(0.3) * 180 / M_PI));
    CHECK(alarm("ASIN[1.0001]") == 119);
    CHECK(alarm("ASIN[-2]") == 119);
    CHECK(number("ACOS[0.5]") == 60);
    CHECK(number("ACOS[0]") == 90);
    CHECK(number("ACOS[1]") == 0);
    CHECK(number("ACOS[-1]") == 180);
    CHECK(number("ACOS[-0.5]", nat1) == 120);   // 0..180 whatever NAT says
    CHECK(alarm("ACOS[1.1]") == 119);
    CHECK(alarm("ACOS[-1.1]") == 119);
    const Evaluated e = eval("1+ASIN[2]");
    CHECK(e.error_text() == "ASIN[2]");
    CHECK(e.result.error->code == "M0119");
}

TEST_CASE("ATAN: ATAN[a]/[b], ATAN[a,b] and one argument") {
    CHECK(number("ATAN[1]/[1]") == 45);
    CHECK(number("ATAN[1]/[-1]") == 135);
    CHECK(number("ATAN[-1]/[-1]") == 225);   // the manual's NAT = 0 example
    CHECK(number("ATAN[-1]/[1]") == 315);
    CHECK(number("ATAN[1]/[0]") == 90);
    CHECK(number("ATAN[-1]/[0]") == 270);
    CHECK(number("ATAN[0]/[-1]") == 180);
    CHECK(number("ATAN[0]/[1]") == 0);
    CHECK(number("ATAN[0]/[0]") == 0);
    CHECK(number("ATAN[#0]/[1]") == 0);
    CHECK(number("ATAN[1]/[SQRT[3]]") == Approx(30));
    CHECK(number("ATAN[1,1]") == 45);
    CHECK(number("ATAN[-1,-1]") == 225);
    CHECK(number("ATAN[1,-1]") == 135);
    Options nat1;
    nat1.angle_range = AngleRange::minus_180_to_180;
    CHECK(number("ATAN[-1]/[-1]", nat1) == -135);   // the manual's NAT = 1 example
    CHECK(number("ATAN[-1,1]", nat1) == -45);
    CHECK(number("ATAN[0]/[-1]", nat1) == 180);
    CHECK(number("ATAN[1]/[1]", nat1) == 45);
    // The two-argument form inside larger expressions.
    CHECK(number("2*ATAN[1]/[1]") == 90);
    CHECK(number("-ATAN[1]/[1]") == -45);
    CHECK(number("-ATAN[1]/[2]*3") == Approx(-3 * std::atan2(1, 2) * 180 / M_PI));
    CHECK(number("ATAN[1]/[1]+1") == 46);
    CHECK(number("90/ATAN[1]/[1]") == 2);   // 90/(ATAN[1]/[1])
    CHECK(number("ATAN[1]/[1]/[3]") == 15);
    CHECK(number("ATAN[1]/[-1]*[2]") == 270);
    // One argument: the principal value, and a bracketed ATAN is an ordinary division.
    CHECK(number("ATAN[1]") == 45);
    CHECK(number("ATAN[-1]") == -45);
    CHECK(number("[ATAN[1]]/[2]") == 22.5);
    CHECK(number("ATAN[1]/2") == 22.5);
    CHECK(alarm("ATAN[1]/[1/0]") == 112);
}

TEST_CASE("atan2_operands recognises exactly ATAN[a]/[b]") {
    const ast::SyntaxTree tree = parse("#1=ATAN[#2]/[#3]\n#4=[ATAN[1]]/[2]\n#5=ATAN[1,2]/[3]\n#6=ATAN[1]/2\n");
    const auto st = statements(tree);
    REQUIRE(st.size() == 4);
    const auto ops = atan2_operands(tree, st[0]->value);
    REQUIRE(ops);
    CHECK(ast::expr_to_string(tree, ops->y) == "#2");
    CHECK(tree.slice(tree.exprs[static_cast<std::size_t>(ops->x)].range()) == "[#3]");
    CHECK_FALSE(atan2_operands(tree, st[1]->value));
    CHECK_FALSE(atan2_operands(tree, st[2]->value));
    CHECK_FALSE(atan2_operands(tree, st[3]->value));
    CHECK_FALSE(atan2_operands(tree, -1));
}

TEST_CASE("SQRT, ABS, LN, EXP, POW") {
    CHECK(number("SQRT[16]") == 4);
    CHECK(number("SQRT[2]") == std::sqrt(2.0));
    CHECK(number("SQRT[0]") == 0);
    CHECK(alarm("SQRT[-1]") == 119);
    CHECK(alarm("SQRT[-0.0001]") == 119);
    CHECK(number("ABS[-3.5]") == 3.5);
    CHECK(number("ABS[2]") == 2);
    CHECK(number("LN[1]") == 0);
    CHECK(number("LN[EXP[2]]") == Approx(2));
    CHECK(number("LN[10]") == std::log(10.0));
    CHECK(alarm("LN[0]") == 119);
    CHECK(alarm("LN[-1]") == 119);
    CHECK(number("EXP[0]") == 1);
    CHECK(number("EXP[1]") == std::exp(1.0));
    CHECK(number("EXP[-1]") == std::exp(-1.0));
    CHECK(number("POW[2,10]") == 1024);
    CHECK(number("POW[2,0.5]") == std::sqrt(2.0));
    CHECK(number("POW[-2,3]") == -8);
    CHECK(number("POW[0,2]") == 0);
    CHECK(number("POW[4,-1]") == 0.25);
    CHECK(alarm("POW[-2,0.5]") == 119);
    CHECK(alarm("POW[0,0]") == 119);
    CHECK(alarm("POW[0,-1]") == 119);
    CHECK(alarm("POW[10,100]") == 111);
}

TEST_CASE("ROUND, FIX, FUP, including negatives") {
    CHECK(number("ROUND[1.2345]") == 1);   // the manual's example
    CHECK(number("ROUND[1.5]") == 2);
    CHECK(number("ROUND[2.5]") == 3);   // half away from zero, not to even
    CHECK(number("ROUND[-1.5]") == -2);
    CHECK(number("ROUND[-1.4]") == -1);
    CHECK(number("ROUND[-2.5]") == -3);
    CHECK(number("ROUND[-0.4]") == 0);
    CHECK_FALSE(std::signbit(number("ROUND[-0.4]")));
    CHECK(number("FIX[1.2]") == 1);
    CHECK(number("FIX[-1.2]") == -1);
    CHECK(number("FIX[1.9]") == 1);
    CHECK(number("FIX[-1.9]") == -1);
    CHECK(number("FIX[2]") == 2);
    CHECK(number("FUP[1.2]") == 2);
    CHECK(number("FUP[-1.2]") == -2);
    CHECK(number("FUP[2]") == 2);
    CHECK(number("FUP[-2]") == -2);
    CHECK(number("FUP[0.0001]") == 1);
    CHECK(number("FUP[#0]") == 0);
    SECTION("ROUND in an NC address rounds to the least input increment") {
        Options address;
        address.round_increment = 0.001;
        Variables vars;
        vars.write(1, Value::of(1.2345));
        vars.write(2, Value::of(2.3456));
        CHECK(number("ROUND[#1]", vars, address) == Approx(1.235));
        CHECK(number("ROUND[#1]+ROUND[#2]", vars, address) == Approx(3.581));
        CHECK(number("#1+#2", vars, address) == Approx(3.5801));
    }
}

TEST_CASE("BIN and BCD conversions") {
    CHECK(number("BCD[123]") == 0x123);
    CHECK(number("BCD[0]") == 0);
    CHECK(number("BCD[99999999]") == 0x99999999u);
    CHECK(number("BIN[291]") == 123);   // 0x123
    CHECK(number("BIN[BCD[4567]]") == 4567);
    CHECK(number("BIN[0]") == 0);
    CHECK(alarm("BIN[26]") == 119);   // 0x1A: A is not a decimal digit
    CHECK(alarm("BIN[-1]") == 119);
    CHECK(alarm("BCD[-1]") == 119);
    CHECK(alarm("BCD[1.5]") == 119);
    CHECK(alarm("BCD[100000000]") == 119);
}

TEST_CASE("ADP: an argument passed without a point is scaled back; any other value is itself") {
    CHECK(number("ADP[10]") == 10);
    CHECK(number("ADP[1.5]") == 1.5);
    Options isb;
    isb.adp_factor = 1000;   // G65 X10 on IS-B metric: #24 = 0.010
    Variables vars;
    vars.write(24, Value::of_increments(0.010));
    CHECK(number("ADP[#24]", vars, isb) == Approx(10));
    vars.write(25, Value::of(0.010));   // G65 Y0.01: written with a point, ADP keeps it
    CHECK(number("ADP[#25]", vars, isb) == Approx(0.010));
    CHECK(number("ADP[1.5]", vars, isb) == 1.5);
}

TEST_CASE("functions: wrong number of arguments is alarm 114") {
    CHECK(alarm("POW[2]") == 114);
    CHECK(alarm("SIN[1,2]") == 114);
    CHECK(alarm("SQRT[4,2]") == 114);
    const Evaluated e = eval("1+POW[2]");
    CHECK(e.error_text() == "POW[2]");
}

// --- variables in expressions --------------------------------------------------------------------

TEST_CASE("indirect variables #[...] and FANUC rounding of the number") {
    Variables vars;
    REQUIRE_FALSE(run("#1=5\n#[#1+1]=7\n", vars));
    CHECK(read(vars, 6) == Value::of(7));
    CHECK(number("#[#1+1]", vars) == 7);
    CHECK(number("#[#1+1]*2", vars) == 14);
    REQUIRE_FALSE(run("#[1.4]=14\n#[1.5]=15\n", vars));
    CHECK(read(vars, 1) == Value::of(14));   // #[1.4] is #1
    CHECK(read(vars, 2) == Value::of(15));   // #[1.5] is #2
    REQUIRE_FALSE(run("#[100+[#2-15]*5]=3\n", vars));
    CHECK(read(vars, 100) == Value::of(3));
    CHECK(eval("#[0.4]", vars).result.value.vacant);   // #0
    CHECK(eval("#[#0]", vars).result.value.vacant);    // a vacant index is 0
    CHECK(number("#[#[2]-13]", vars) == 15);           // #[#2-13] = #[15-13] = #2
}

TEST_CASE("variable_number: rounding and range") {
    const ast::SyntaxTree tree = parse("#[2.5]=1\n#[-0.6]=1\n#[#0]=1\n#17=1\n");
    const auto st = statements(tree);
    Variables vars;
    CHECK(variable_number(tree, st[0]->target, vars).number == 3);
    const NumberResult negative = variable_number(tree, st[1]->target, vars);
    REQUIRE(negative.error);
    CHECK(negative.error->alarm == 115);
    CHECK(variable_number(tree, st[2]->target, vars).number == 0);
    CHECK(variable_number(tree, st[3]->target, vars).number == 17);
    CHECK(variable_number(tree, st[3]->value, vars).error->code == "M0901");   // not a variable
}

TEST_CASE("undefined variable numbers are alarm 115 with the variable's range") {
    Variables vars;
    const Evaluated e = eval("1+#34", vars);
    REQUIRE(e.result.error);
    CHECK(e.result.error->alarm == 115);
    CHECK(e.result.error->code == "M0115");
    CHECK(e.error_text() == "#34");
    CHECK(alarm("#[0-1]", vars) == 115);
    CHECK(alarm("#200", vars) == 115);
    CHECK(alarm("#1000", vars) == 115);   // no system variables without a SystemVariables
    const auto w = run("#200=1\n", vars);
    REQUIRE(w);
    CHECK(w->alarm == 115);
    const auto w2 = run("#[-1]=1\n", vars);
    REQUIRE(w2);
    CHECK(w2->alarm == 115);
}

TEST_CASE("writes to #0 and read-only variables are alarm 116") {
    TestSystem system;
    Variables vars(system);
    const ast::SyntaxTree tree = parse("#0=1\n");
    const auto err = assign(tree, *statements(tree)[0], vars);
    REQUIRE(err);
    CHECK(err->alarm == 116);
    CHECK(err->code == "M0116");
    CHECK(tree.slice(err->range) == "#0");
    CHECK(run("#[#0]=1\n", vars)->alarm == 116);
    CHECK(run("#4001=2\n", vars)->alarm == 116);
    system.protected_numbers = {510};
    CHECK(run("#510=1\n", vars)->alarm == 116);
    CHECK_FALSE(run("#511=1\n", vars));
    CHECK(run("#3000=999\n", vars)->alarm == 119);   // refused value
    REQUIRE_FALSE(run("#3000=12\n#1=#5001+#4001\n", vars));
    CHECK(read(vars, 1) == Value::of(13.5));
    CHECK(system.values[3000] == Value::of(12));
}

TEST_CASE("assignments see earlier ones; locals per level") {
    Variables vars;
    REQUIRE_FALSE(run("#1=2\n#2=#1*#1\n#100=#2+1\n#500=#100*2\n", vars));
    CHECK(read(vars, 2) == Value::of(4));
    CHECK(read(vars, 500) == Value::of(10));
    vars.push_level();
    REQUIRE_FALSE(run("#3=#1\n#4=#100\n", vars));
    CHECK(read(vars, 3).vacant);   // the caller's #1 is not visible
    CHECK(read(vars, 4) == Value::of(5));
    vars.pop_level();
    CHECK(read(vars, 3).vacant);
    CHECK(read(vars, 1) == Value::of(2));
}

TEST_CASE("assign: a failed value leaves the target unchanged") {
    Variables vars;
    vars.write(1, Value::of(1));
    const auto err = run("#1=1/0\n", vars);
    REQUIRE(err);
    CHECK(err->alarm == 112);
    CHECK(read(vars, 1) == Value::of(1));
}

// --- nesting -------------------------------------------------------------------------------------

TEST_CASE("brackets nest five levels deep, function brackets included (alarm 118)") {
    CHECK(number("[[[[[1]]]]]") == 1);
    CHECK(number("SIN[[[[0]]]]") == 0);
    CHECK(alarm("[[[[[[1]]]]]]") == 118);
    CHECK(number("SIN[[[[[0]]]]]") == 0);   // five levels with the function's
    CHECK(alarm("SIN[[[[[[0]]]]]]") == 118);
    CHECK(eval("#[[[[[1]]]]]").result.ok());
    CHECK(alarm("#[[[[[[1]]]]]]") == 118);   // #[ ] is a bracket too
    Options unlimited;
    unlimited.max_nesting = 0;
    CHECK(number("[[[[[[[[1]]]]]]]]", unlimited) == 1);
    const Evaluated e = eval("[[[[[[1]]]]]]");
    CHECK(e.result.error->code == "M0118");
    // The brackets of IF count as a level.
    Variables vars;
    CHECK(holds("[[[[1]]]] EQ 1", vars));
    CHECK(condition("[[[[[1]]]]] EQ 1", vars).result.error->alarm == 118);
}

// --- odds and ends -------------------------------------------------------------------------------

TEST_CASE("errors convert to diagnostics; bad indices are reported, not crashes") {
    Variables vars;
    const Evaluated e = eval("SQRT[-4]", vars);
    REQUIRE(e.result.error);
    const ast::Diagnostic d = to_diagnostic(*e.result.error);
    CHECK(d.code == "M0119");
    CHECK(d.severity == ast::Severity::error);
    CHECK(d.range == e.result.error->range);
    CHECK(d.message == e.result.error->message);
    const Result bad = evaluate(e.tree, 100000, vars);
    REQUIRE(bad.error);
    CHECK(bad.error->code == "M0901");
    const ConditionResult bad_condition = evaluate_condition(e.tree, -1, vars);
    REQUIRE(bad_condition.error);
    CHECK_FALSE(bad_condition.value);
}

TEST_CASE("IF/WHILE statements from program text") {
    Variables vars;
    vars.write(1, Value::of(3));
    const ast::SyntaxTree tree = parse("WHILE [#1 GT 0] DO 1\nIF [#1 EQ 3] THEN #2=1\nIF [#1 LT 0] GOTO 10\n");
    const auto st = statements(tree);
    REQUIRE(st.size() == 3);
    CHECK(evaluate_condition(tree, st[0]->value, vars).value == true);
    CHECK(evaluate_condition(tree, st[1]->value, vars).value == true);
    CHECK(evaluate_condition(tree, st[2]->value, vars).value == false);
    const ast::Statement& then = tree.statements[static_cast<std::size_t>(st[1]->then_statement)];
    REQUIRE_FALSE(assign(tree, then, vars));
    CHECK(read(vars, 2) == Value::of(1));
    const auto not_assign = assign(tree, *st[0], vars);
    REQUIRE(not_assign);
    CHECK(not_assign->code == "M0901");
}
