// The files of a load path's checkpoint (doc/theory.md §11, "Restart"):
// after every <Output/Checkpoint interval>-th later step the folder
// checkpoint/ in the output folder holds the mesh with the fields on its
// cells (p4est's save, written by ContactProblem::write_checkpoint()), the
// record of the path's state (state.txt, written and read here) and the
// parameters of the run (parameters.prm). `dualcontact scene.prm --resume
// folder/` goes on from it (ContactProblem::resume_from_checkpoint()).
#ifndef dualcontact_checkpoint_h
#define dualcontact_checkpoint_h

#include <map>
#include <set>
#include <string>

namespace dualcontact
{
  /** The checkpoint folder of the output folder `directory`. */
  std::string
  checkpoint_folder(const std::string &directory);

  /**
   * The scalars of a checkpoint: one "key value" per line, the numbers in
   * 17 significant digits, so that they read back exactly.
   */
  class CheckpointRecord
  {
  public:
    void
    set(const std::string &key, const std::string &value);
    void
    set(const std::string &key, const double value);

    /** The value of `key`; throws if the record lacks it. */
    const std::string &
    text(const std::string &key) const;
    double
    number(const std::string &key) const;

    /** Every key that begins with `prefix`, with its value. */
    std::map<std::string, std::string>
    with_prefix(const std::string &prefix) const;

    void
    write(const std::string &filename) const;

    /** Read `filename`; false if there is none. */
    bool
    read(const std::string &filename);

  private:
    std::map<std::string, std::string> values;
  };

  /**
   * The first entry (in the order of `now`) whose value differs between two
   * parameter listings in ParameterHandler's PRM format, or that only one
   * of them has, as "<Subsection/Entry> is 'a' in the scene and 'b' in the
   * checkpoint"; empty if they agree. The entries in `ignored`
   * ("Subsection/Entry") do not count.
   */
  std::string
  first_difference(const std::string           &now,
                   const std::string           &saved,
                   const std::set<std::string> &ignored);
} // namespace dualcontact

#endif
