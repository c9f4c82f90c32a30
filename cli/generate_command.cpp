// orthoray generate FAMILY: write a scene of one of the instance families.
#include "commands.hpp"
#include "option_checks.hpp"
#include "orthoray/generate.hpp"
#include "output_file.hpp"
#include "stop_at_once.hpp"

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

namespace orthoray::cli {

struct GenerateArgs {
    std::string family, output;
    std::uint64_t seed = 1;
    // random
    int dim = 2;
    std::int64_t mirrors = 20, range = 1000, denominator = 1, direction_size = 10;
    unsigned bits = 0;
    std::string absorbers = "0", splitters = "0", one_sided = "0", diagonals = "0";
    std::int64_t rays = 1, targets = 1;
    bool box = false;
    std::int64_t target_after = 0;
    // box, square
    std::vector<std::string> sides = {"3", "5"}, start, direction, target_point;
    std::string target = "reached";
    // hallway
    std::string length = "1000", slope = "1/10";
    // coprime-box, coprime-cuboid
    unsigned k = 4;
};

namespace {

// Which options each family reads; any other family option is a usage error.
const std::map<std::string, std::set<std::string>> family_options{
    {"random",
     {"--dim", "--mirrors", "--absorbers", "--splitters", "--one-sided", "--diagonals", "--rays",
      "--targets", "--range", "--bits", "--denominator", "--box", "--target-after",
      "--direction-size"}},
    {"box", {"--sides", "--start", "--direction", "--target", "--target-point"}},
    {"square", {"--direction"}},
    {"hallway", {"--length", "--slope"}},
    {"coprime-box", {"--k", "--target"}},
    {"coprime-cuboid", {"--k", "--target"}},
};

const std::map<std::string, BoxFamily::Target> targets{{"reached", BoxFamily::Target::reached},
                                                       {"far", BoxFamily::Target::far},
                                                       {"generic", BoxFamily::Target::generic}};

Rational number(const std::string& text, const std::string& option) {
    const NumberToken token = read_number(text);
    if (token.status != NumberToken::Status::ok)
        throw UsageError("found '" + text + "' for " + option + ", expected a number");
    return token.value;
}

Integer whole(const std::string& text, const std::string& option) {
    const Rational x = number(text, option);
    if (x.get_den() != 1)
        throw UsageError("found '" + text + "' for " + option + ", expected an integer");
    return x.get_num();
}

// A chance: a fraction in [0, 1] with a denominator the generator can draw.
Rational chance(const std::string& text, const std::string& option) {
    const Rational x = number(text, option);
    if (x < 0 || x > 1 || x.get_den() > RandomFamily::max_denominator)
        throw UsageError("found '" + text + "' for " + option +
                         ", expected a fraction from 0 to 1 with a denominator up to 2^20");
    return x;
}

Rational above_zero(const std::string& text, const std::string& option) {
    const Rational x = number(text, option);
    if (x <= 0)
        throw UsageError("found '" + text + "' for " + option + ", expected a number above 0");
    return x;
}

Integer side(const std::string& text, const std::string& option) {
    const Integer x = whole(text, option);
    if (x <= 0)
        throw UsageError("found '" + text + "' for " + option + ", expected a positive integer");
    return x;
}

Integer nonzero(const std::string& text, const std::string& option) {
    const Integer x = whole(text, option);
    if (x == 0)
        throw UsageError("found '" + text + "' for " + option + ", expected a nonzero integer");
    return x;
}

Vector point(const std::vector<std::string>& words, std::size_t dim, const std::string& option) {
    if (words.size() != dim)
        throw UsageError("found " + std::to_string(words.size()) + " numbers for " + option +
                         ", expected " + std::to_string(dim));
    Vector v;
    for (std::size_t j = 0; j < dim; ++j) v[j] = number(words[j], option);
    return v;
}

GeneratedScene build(const GenerateArgs& a, const CLI::App& cmd) {
    auto given = [&](const std::string& option) { return cmd.get_option(option)->count() > 0; };
    if (a.family == "random") {
        RandomFamily f;
        f.dim = a.dim;
        f.mirrors = a.mirrors;
        f.absorbers = chance(a.absorbers, "--absorbers");
        f.splitters = chance(a.splitters, "--splitters");
        f.one_sided = chance(a.one_sided, "--one-sided");
        f.diagonals = chance(a.diagonals, "--diagonals");
        f.rays = a.rays;
        f.targets = a.targets;
        f.range = given("--bits") ? std::int64_t{1} << a.bits : a.range;
        f.denominator = a.denominator;
        f.box = a.box;
        if (given("--target-after")) f.target_after = a.target_after;
        f.direction_size = a.direction_size;
        f.seed = a.seed;
        return generate_random(f);
    }
    if (a.family == "box") {
        BoxFamily f;
        f.sides.clear();
        for (const std::string& s : a.sides) f.sides.push_back(side(s, "--sides"));
        const std::size_t dim = f.sides.size();
        if (dim != 2 && dim != 3)
            throw UsageError("found " + std::to_string(dim) +
                             " numbers for --sides, expected 2 or 3");
        if (given("--start")) f.start = point(a.start, dim, "--start");
        if (given("--direction")) f.direction = point(a.direction, dim, "--direction");
        f.target = targets.at(a.target);
        if (given("--target-point")) {
            if (given("--target"))
                throw UsageError("found both --target and --target-point, expected one of them");
            f.target = BoxFamily::Target::point;
            f.target_point = point(a.target_point, dim, "--target-point");
        }
        return generate_box(f);
    }
    if (a.family == "square") {
        const std::vector<std::string> pq =
            given("--direction") ? a.direction : std::vector<std::string>{"3", "2"};
        if (pq.size() != 2)
            throw UsageError("found " + std::to_string(pq.size()) +
                             " numbers for --direction, expected 2 (p q)");
        return generate_square(nonzero(pq[0], "--direction"), nonzero(pq[1], "--direction"));
    }
    if (a.family == "hallway")
        return generate_hallway(above_zero(a.length, "--length"), above_zero(a.slope, "--slope"));
    if (a.family == "coprime-box") return generate_coprime_box(a.k, targets.at(a.target));
    if (a.k < 2)
        throw UsageError("found '" + std::to_string(a.k) +
                         "' for --k, expected a whole number from 2 to 4096 for coprime-cuboid");
    return generate_coprime_cuboid(a.k, targets.at(a.target));
}

// What the family takes, for a message: "one of its options: --k, --target, --seed".
std::string options_of(const std::string& family) {
    std::string list = "one of its options: ";
    for (const std::string& option : family_options.at(family)) list += option + ", ";
    return list + "--seed";
}

// The command line that makes this scene again, for the file's header;
// refuses an option the family does not take.
std::string checked_header(const GenerateArgs& args, const CLI::App& cmd) {
    const std::set<std::string>& allowed = family_options.at(args.family);
    std::string header = "orthoray generate " + args.family;
    for (const CLI::Option* option : cmd.get_options()) {
        const std::string name = option->get_name();
        if (option->count() == 0 || name == "FAMILY" || name == "--output" || name == "--help")
            continue;
        if (name != "--seed" && !allowed.contains(name))
            throw UsageError("found " + name + " for the family " + args.family + ", expected " +
                             options_of(args.family) + " (see 'orthoray generate --help')");
        header += ' ' + name;
        // A flag (--box) takes no value on the command line, though CLI11
        // records one ("true"): written, it would not parse again.
        if (option->get_expected_max() == 0) continue;
        for (const std::string& word : option->results()) header += ' ' + word;
    }
    return header;
}

GeneratedScene checked_build(const GenerateArgs& args, const CLI::App& cmd) {
    try {
        return build(args, cmd);
    } catch (const std::invalid_argument& e) {
        throw UsageError(args.family + ": " + e.what());
    }
}

int run(const GenerateArgs& args, const CLI::App& cmd) {
    const std::string header = checked_header(args, cmd);
    const std::string text = write_generated(checked_build(args, cmd), {header});
    // Decided: until here a signal stopped the command at once (main.cpp),
    // with nothing written; from here on it would cut the scene short.
    stop_no_more();
    if (cmd.get_option("--output")->count() == 0) {
        std::cout << text;
        return yes;
    }
    OutputFile out(args.output, {}, "the scene");
    out.stream() << text;
    out.commit();
    return yes;
}

// Registers `generate` and its options on `app`, parsed into `args`.
CLI::App* register_generate(CLI::App& app, const std::shared_ptr<GenerateArgs>& args) {
    CLI::App* cmd = app.add_subcommand(
        "generate",
        "Write a scene of an instance family (docs/generate.md). The same arguments give the\n"
        "same bytes on every machine. Where the answer is known in closed form or by\n"
        "construction it is written as a comment '# expect: yes hit N' (or 'no cycle N', ...).\n\n"
        "Families and an example each:\n"
        "  random          random mirrors (and absorbers, splitters, one-sided elements,\n"
        "                  diagonals in 2D), optionally boxed, with one or more rays and\n"
        "                  targets\n"
        "                    orthoray generate random --dim 2 --mirrors 50 --box --target-after 20 "
        "--seed 7\n"
        "                    orthoray generate random --mirrors 30 --splitters 1/3 --one-sided 1/4 "
        "--rays 2 --targets 3 --box\n"
        "                    orthoray generate random --mirrors 12 --diagonals 1/2 --box "
        "--target-after 8\n"
        "  box             the closed mirror box a x b (x c), from the corner 0 at 45 degrees\n"
        "                  (or --start/--direction); target reached, far, generic or a point\n"
        "                    orthoray generate box --sides 3 5 --target far\n"
        "  square          the unit mirror square, direction (p, q), generic start: period "
        "2(p+q)\n"
        "                    orthoray generate square --direction 5 3\n"
        "  hallway         mirrors y = 0 and y = 1 on [0, L], a ray of small slope\n"
        "                    orthoray generate hallway --length 10000 --slope 1/100\n"
        "  coprime-box     the (2^k + 1) x 2^k box: 2^(k+1) - 1 reflections to a corner\n"
        "                    orthoray generate coprime-box --k 20\n"
        "  coprime-cuboid  the (2^k + 1) x 2^k x (2^k - 1) box: about 3 * 4^k reflections\n"
        "                    orthoray generate coprime-cuboid --k 6 --target far\n\n"
        "Exit status: 0 written, 2 bad usage (an option the family does not take, a bad number).");
    cmd->add_option("FAMILY", args->family,
                    "random, box, square, hallway, coprime-box, coprime-cuboid")
        ->required()
        ->check(one_of({"random", "box", "square", "hallway", "coprime-box", "coprime-cuboid"}));
    cmd->add_option("-o,--output", args->output, "write the scene to this file (default: stdout)")
        ->check(not_empty("a file name"));
    cmd->add_option("--seed", args->seed,
                    "the seed of std::mt19937_64 for random (default 1), 0 to 2^64 - 1; the other "
                    "families are fixed by their parameters and only record it")
        ->transform(whole_number_u64());
    cmd->add_option("--dim", args->dim, "random: dimension 2 or 3 (default 2)")
        ->check(one_of({"2", "3"}));
    cmd->add_option("--mirrors", args->mirrors,
                    "random: number of elements, 0 to 10^6 (default 20)")
        ->transform(whole_number_in(0, RandomFamily::max_mirrors));
    cmd->add_option("--absorbers", args->absorbers,
                    "random: the chance an element absorbs, a fraction like 1/10 (default 0)");
    cmd->add_option("--splitters", args->splitters,
                    "random: the chance an element that does not absorb is a splitter, a "
                    "fraction like 1/3 (default 0)");
    cmd->add_option("--one-sided", args->one_sided,
                    "random: the chance an element is one-sided (x+ or x-, alike), a fraction "
                    "(default 0)");
    cmd->add_option("--diagonals", args->diagonals,
                    "random, 2D: the chance an element lies on a diagonal, '/' or '\\' alike "
                    "(docs/octagonal.md), a fraction (default 0)");
    cmd->add_option("--rays", args->rays,
                    "random: the number of rays, 1 to 1000 (default 1), each a random start and "
                    "direction")
        ->transform(whole_number_in(1, RandomFamily::max_rays));
    cmd->add_option("--targets", args->targets,
                    "random: the number of targets, 1 to 1000 (default 1), random points; "
                    "--target-after needs 1 ray, 1 target and no splitters")
        ->transform(whole_number_in(1, RandomFamily::max_targets));
    CLI::Option* range =
        cmd->add_option("--range", args->range,
                        "random: coordinates in [0, R], R from 2 to 2^62 / Q (default 1000)")
            ->transform(whole_number_in(2, RandomFamily::max_range));
    cmd->add_option("--bits", args->bits, "random: coordinates in [0, 2^B] (instead of --range)")
        ->excludes(range)
        ->transform(whole_number_in(1, 40));
    cmd->add_option("--denominator", args->denominator,
                    "random: each number is k/q with q in 1..Q, Q up to 2^20 (default 1: integers)")
        ->transform(whole_number_in(1, RandomFamily::max_denominator));
    cmd->add_flag("--box", args->box, "random: also the closed mirror box [0, R]^dim");
    cmd->add_option("--target-after", args->target_after,
                    "random: the target is the midpoint of the segment after K reflections (the "
                    "answer is then known: yes), K up to 10^6; without it, a random point")
        ->transform(whole_number_in(0, RandomFamily::max_target_after));
    cmd->add_option("--direction-size", args->direction_size,
                    "random: direction components are nonzero integers in [-D, D], D up to 2^40 "
                    "(default 10)")
        ->transform(whole_number_in(1, RandomFamily::max_direction_size));
    cmd->add_option("--sides", args->sides, "box: 2 or 3 positive integer sides (default 3 5)")
        ->expected(2, 3);
    cmd->add_option("--start", args->start, "box: the start point (default the corner 0)")
        ->expected(2, 3);
    cmd->add_option("--direction", args->direction,
                    "box: the direction (default all ones); square: p q (default 3 2)")
        ->expected(2, 3);
    cmd->add_option("--target", args->target,
                    "box, coprime-box, coprime-cuboid: reached (default: the corner the 45-degree "
                    "ray reaches), far (the corner opposite 0) or generic (a point never reached)")
        ->check(one_of({"reached", "far", "generic"}));
    cmd->add_option("--target-point", args->target_point, "box: the target point")->expected(2, 3);
    cmd->add_option("--length", args->length, "hallway: the mirrors' length L (default 1000)");
    cmd->add_option("--slope", args->slope, "hallway: the ray's slope, > 0 (default 1/10)");
    cmd->add_option("--k", args->k,
                    "coprime-box, coprime-cuboid: the sides' bit size k (default 4; "
                    "coprime-cuboid from 2)")
        ->transform(whole_number_in(1, 4096));
    return cmd;
}

} // namespace

Command add_generate(CLI::App& app) {
    auto args = std::make_shared<GenerateArgs>();
    CLI::App* cmd = register_generate(app, args);
    return [args, cmd] { return run(*args, *cmd); };
}

SceneGenerator::SceneGenerator(const std::string& words)
    : parser_(std::make_shared<CLI::App>()), args_(std::make_shared<GenerateArgs>()) {
    cmd_ = register_generate(*parser_, args_);
    std::vector<std::string> argv{"generate"};
    std::istringstream in(words);
    for (std::string word; in >> word;) argv.push_back(word);
    // CLI11 takes the words last first.
    std::reverse(argv.begin(), argv.end());
    try {
        parser_->parse(argv);
    } catch (const CLI::ParseError& e) {
        throw UsageError("--generate '" + words + "': " + e.what());
    }
    if (cmd_->get_option("--seed")->count() > 0 || cmd_->get_option("--output")->count() > 0)
        throw UsageError("--generate '" + words +
                         "': the seeds come from --seeds, and nothing is "
                         "written");
    checked_header(*args_, *cmd_); // refuses options the family does not take
    scene(args_->seed);            // the family's own checks, once, before any instance
}

Scene SceneGenerator::scene(std::uint64_t seed) const {
    GenerateArgs args = *args_;
    args.seed = seed;
    return checked_build(args, *cmd_).scene;
}

} // namespace orthoray::cli
