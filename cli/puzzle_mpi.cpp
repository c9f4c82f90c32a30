#include "puzzle_mpi.hpp"

#include "mpi_link.hpp"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <sstream>
#include <thread>

namespace orthoray::cli {
namespace {

// Messages. A rank asks for work with the result of its last piece ("JOB
// PIECE\n" and the result's text; empty the first time). Rank 0 answers
// with a piece ("JOB PIECE\n" and the search's text), or with an empty
// quit message; it cancels a running piece with "JOB".
enum Tag : int { ask = 11, piece = 12, cancel = 13, quit = 14 };

// Between polls of rank 0's mailbox: short against a piece's milliseconds.
constexpr auto poll_pause = std::chrono::microseconds(200);

// A worker looks for a cancel message every this many nodes: MPI_Iprobe
// costs about a microsecond, a node a fraction of one.
constexpr std::uint64_t cancel_check_nodes = 1024;

std::pair<std::uint64_t, std::size_t> job_and_piece(const std::string& message, std::size_t* body) {
    std::istringstream in(message.substr(0, message.find('\n')));
    std::uint64_t job = 0;
    std::size_t index = 0;
    in >> job >> index;
    *body = message.find('\n') + 1;
    return {job, index};
}

} // namespace

PieceCoordinator::PieceCoordinator(int ranks, const std::atomic<bool>* stop,
                                   std::atomic<std::uint64_t>* progress)
    : ranks_(ranks), stop_(stop), progress_(progress) {}

bool PieceCoordinator::take_request(std::optional<Arrived>* arrived) {
    int pending = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, ask, MPI_COMM_WORLD, &pending, &status);
    if (!pending) return false;
    const std::string message = receive(status);
    idle_.push_back(status.MPI_SOURCE);
    if (message.empty()) return true; // a rank's first request
    std::erase_if(busy_, [&](const auto& b) { return b.first == status.MPI_SOURCE; });
    std::size_t body = 0;
    const auto [job, index] = job_and_piece(message, &body);
    if (job == job_)
        arrived->emplace(index, lazor_piece_from_text(std::string_view(message).substr(body)));
    return true;
}

std::vector<std::optional<LazorPieceResult>>
PieceCoordinator::run(const LazorSearchPieces& pieces) {
    ++job_;
    const std::string head = std::to_string(job_) + ' ';
    const std::string text = pieces.to_text();
    std::vector<std::optional<LazorPieceResult>> results(pieces.size());
    std::mutex mutex; // guards results and next
    std::size_t next = 0;
    std::atomic<bool> halted{false}, local_done{false};
    const std::function<bool()> halt = [&] {
        return halted.load(std::memory_order_relaxed) ||
               (stop_ && stop_->load(std::memory_order_relaxed));
    };
    // Rank 0 searches too: with 2 ranks, two pieces run at a time.
    std::thread local([&] {
        for (;;) {
            std::size_t index = 0;
            {
                const std::lock_guard<std::mutex> lock(mutex);
                if (halted || next >= results.size()) break;
                index = next++;
            }
            LazorPieceResult result = pieces.search(index, halt, progress_);
            const std::lock_guard<std::mutex> lock(mutex);
            results[index] = std::move(result);
        }
        local_done = true;
    });
    for (;;) {
        bool decided = false, all_given = false;
        {
            const std::lock_guard<std::mutex> lock(mutex);
            decided = pieces.outcome(results).has_value();
            all_given = next >= results.size();
        }
        if (!halted && (decided || (stop_ && stop_->load()))) {
            halted = true;
            for (const auto& [rank, index] : busy_) send(std::to_string(job_), rank, cancel);
        }
        if ((halted || all_given) && busy_.empty() && local_done) break;
        while (!halted && !idle_.empty()) {
            std::size_t index = 0;
            {
                const std::lock_guard<std::mutex> lock(mutex);
                if (next >= results.size()) break;
                index = next++;
            }
            const int rank = idle_.back();
            idle_.pop_back();
            busy_.emplace_back(rank, index);
            std::string message = head;
            message += std::to_string(index) + '\n';
            message += text;
            send(message, rank, piece);
        }
        std::optional<Arrived> arrived;
        if (!take_request(&arrived)) {
            std::this_thread::sleep_for(poll_pause);
            continue;
        }
        if (!arrived) continue;
        if (progress_) progress_->fetch_add(arrived->second.nodes, std::memory_order_relaxed);
        const std::lock_guard<std::mutex> lock(mutex);
        results[arrived->first] = std::move(arrived->second);
    }
    local.join();
    return results;
}

void PieceCoordinator::finish() {
    while (static_cast<int>(idle_.size()) < ranks_ - 1) {
        std::optional<Arrived> ignored;
        if (!take_request(&ignored)) std::this_thread::sleep_for(poll_pause);
    }
    for (const int rank : idle_) send({}, rank, quit);
    idle_.clear();
}

void serve_pieces(const std::atomic<bool>& stop) {
    send({}, 0, ask);
    std::uint64_t cached_job = 0;
    std::optional<LazorSearchPieces> pieces;
    for (;;) {
        MPI_Status status;
        MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
        const std::string message = receive(status);
        if (status.MPI_TAG == quit) return;
        if (status.MPI_TAG == cancel) continue; // for a piece already done
        std::size_t body = 0;
        const auto [job, index] = job_and_piece(message, &body);
        if (job != cached_job || !pieces) {
            pieces = LazorSearchPieces::from_text(std::string_view(message).substr(body));
            cached_job = job;
        }
        const std::string this_job = std::to_string(job);
        std::uint64_t calls = 0;
        bool cancelled = false;
        const std::function<bool()> halt = [&] {
            if (cancelled || stop.load(std::memory_order_relaxed)) return true;
            if (++calls % cancel_check_nodes != 0) return false;
            for (int pending = 1; pending;) {
                MPI_Status probed;
                MPI_Iprobe(0, cancel, MPI_COMM_WORLD, &pending, &probed);
                if (pending && receive(probed) == this_job) cancelled = true;
            }
            return cancelled;
        };
        const LazorPieceResult result = pieces->search(index, halt);
        send(this_job + ' ' + std::to_string(index) + '\n' + lazor_piece_text(result), 0, ask);
    }
}

} // namespace orthoray::cli
